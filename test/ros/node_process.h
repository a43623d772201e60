// The sim_node process the rostests run against, as a test reads it from
// outside: its process id (through its own XML-RPC server, as rosnode info
// asks) and its resident memory.
#pragma once

#include <ros/network.h>
#include <ros/ros.h>
#include <xmlrpcpp/XmlRpcClient.h>

#include <fstream>
#include <string>

namespace rbs_test {

/// sim_node's process id, as rosnode info asks it: the node's own XML-RPC getPid.
inline int simNodePid() {
  XmlRpc::XmlRpcValue args, result, uri;
  args[0] = ros::this_node::getName();
  args[1] = "/sim_node";
  if (!ros::master::execute("lookupNode", args, result, uri, true)) return -1;
  std::string host;
  uint32_t port = 0;
  if (!ros::network::splitURI(uri, host, port)) return -1;
  XmlRpc::XmlRpcClient client(host.c_str(), static_cast<int>(port), "/");
  XmlRpc::XmlRpcValue ask, answer;
  ask[0] = ros::this_node::getName();
  if (!client.execute("getPid", ask, answer) || answer.size() < 3) return -1;
  return static_cast<int>(answer[2]);
}

/// Its resident memory (VmRSS), kB.
inline long residentKb(int pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string key;
  long kb = -1;
  while (status >> key) {
    if (key == "VmRSS:") status >> kb;
    status.ignore(1 << 12, '\n');
  }
  return kb;
}

}  // namespace rbs_test
