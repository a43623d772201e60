#!/usr/bin/env python3
"""Calls a service from T threads, N times each, with rospy, and counts the
calls that fail, by message (bench/service_churn.sh).

    service_hammer.py SERVICE N T [persistent 0|1]
"""
import collections
import sys
import threading

import rospy
from rigid_body_sim.srv import GetState, GetStateRequest
from std_srvs.srv import Trigger, TriggerRequest


def main():
    service, calls, threads = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    persistent = len(sys.argv) > 4 and sys.argv[4] == "1"
    rospy.init_node("service_hammer", anonymous=True)
    get_state = "get_state" in service
    errors = collections.Counter()
    ok = [0]
    lock = threading.Lock()

    def work():
        proxy = rospy.ServiceProxy(service, GetState if get_state else Trigger, persistent=persistent)
        for _ in range(calls):
            req = GetStateRequest(body="box") if get_state else TriggerRequest()
            try:
                proxy(req)
                with lock:
                    ok[0] += 1
            except (rospy.ServiceException, OSError) as e:
                with lock:
                    errors[str(e)[:120]] += 1

    pool = [threading.Thread(target=work) for _ in range(threads)]
    for t in pool:
        t.start()
    for t in pool:
        t.join()
    mode = "persistent" if persistent else "one connection per call"
    print("rospy %s %s: %d ok, %d failed" % (mode, service, ok[0], sum(errors.values())))
    for message, count in errors.items():
        print("  %d x %s" % (count, message))


if __name__ == "__main__":
    main()
