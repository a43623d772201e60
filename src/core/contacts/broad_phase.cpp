// The broad phase (docs/physics.md §5.1): sweep and prune between bodies.
#include "broad_phase.h"

#include <algorithm>
#include <cmath>

#include "step/scratch.h"

namespace rigid_body_sim::core {

using detail::StepScratch;

namespace {

/// `all` sorted by (a, o) into `sorted`, in time linear in N and the pairs:
/// counted by a, then each body's few by o. std::sort's N log N was 3.5 % of
/// a step at N = 10,000 against 2.4 % at N = 1000 (bench/HISTORY.md).
void sortDirections(int n, const std::vector<std::pair<int, int>>& all, std::vector<int>& starts,
                    std::vector<std::pair<int, int>>& sorted) {
  starts.assign(n + 1, 0);
  for (const auto& d : all) ++starts[d.first + 1];
  for (int a = 0; a < n; ++a) starts[a + 1] += starts[a];
  sorted.resize(all.size());
  for (const auto& d : all) sorted[starts[d.first]++] = d;  // starts[a] moves to a's end
  for (int a = 0, begin = 0; a < n; begin = starts[a++]) {
    std::sort(sorted.begin() + begin, sorted.begin() + starts[a]);
  }
}

}  // namespace

void broadPhase(const Model& model, const State& state, int parts, Workspace& ws) {
  StepScratch& sc = *ws.scratch;
  const int n = static_cast<int>(model.bodyCount());
  std::vector<int>& order = sc.sweep_order;
  if (static_cast<int>(order.size()) != n) {
    order.resize(n);
    for (int i = 0; i < n; ++i) order[i] = i;
  }
  std::vector<double>& lo = sc.box_lo;  // 3 per body, by body index
  std::vector<double>& hi = sc.box_hi;
  std::vector<double>& strip = sc.box_strip;  // per body
  lo.resize(3 * n);
  hi.resize(3 * n);
  strip.resize(n);
  double width = 0.0;  // m: of the widest box
  for (int i = 0; i < n; ++i) {
    const double e = model.body(i).bound_radius + sc.margins[i];
    width = std::max(width, 2.0 * e);
    for (int a = 0; a < 3; ++a) {
      lo[3 * i + a] = state.bodies[i].p_WB(a) - e;
      hi[3 * i + a] = state.bodies[i].p_WB(a) + e;
    }
  }
  const double strip_width = width > 0.0 ? width : 1.0;  // m (no box has size: any width will do)
  for (int i = 0; i < n; ++i) strip[i] = std::floor(state.bodies[i].p_WB.y() / strip_width);
  // Insertion sort on (strip, lo x): the bodies barely move between steps, so this is nearly linear.
  const auto before = [&](int a, int b) {
    return strip[a] < strip[b] || (strip[a] == strip[b] && lo[3 * a] < lo[3 * b]);
  };
  for (int k = 1; k < n; ++k) {
    const int v = order[k];
    int m = k - 1;
    while (m >= 0 && before(v, order[m])) {
      order[m + 1] = order[m];
      --m;
    }
    order[m + 1] = v;
  }
  // Per place in the order: lo x, hi x, lo y, hi y, lo z, hi z, strip, and
  // where the next strip starts.
  constexpr int kStride = 8;
  sc.sorted_boxes.resize(kStride * n);
  for (int k = 0; k < n; ++k) {
    const int i = order[k];
    double* b = &sc.sorted_boxes[kStride * k];
    b[0] = lo[3 * i];
    b[1] = hi[3 * i];
    b[2] = lo[3 * i + 1];
    b[3] = hi[3 * i + 1];
    b[4] = lo[3 * i + 2];
    b[5] = hi[3 * i + 2];
    b[6] = strip[i];
  }
  for (int k = n - 1, next = n; k >= 0; --k) {
    if (k + 1 < n && sc.sorted_boxes[kStride * (k + 1) + 6] != sc.sorted_boxes[kStride * k + 6]) next = k + 1;
    sc.sorted_boxes[kStride * k + 7] = next;
  }
  // The sweep: each box against the boxes after it in its strip that start
  // before it ends, and against the boxes of the next strip (if it is the
  // neighbouring one) that overlap it in x; two sleepers make no pair. In
  // `parts` contiguous runs of the order, each run's directions in its own
  // list, then merged and sorted.
  const double* box = sc.sorted_boxes.data();
  detail::runParts(ws, parts, [&](int part) {
    std::vector<std::pair<int, int>>& pairs = sc.parts[part].directions;
    pairs.clear();
    const Range range = partRange(n, part, parts);
    const int begin = static_cast<int>(range.begin), end = static_cast<int>(range.end);
    const bool grouped = model.hasCollisionGroups();
    const auto apart = [&](int a, int b) {  // one collision group: never touch (an articulation's links)
      const int group = model.body(a).collision_group;
      return group >= 0 && group == model.body(b).collision_group;
    };
    const auto overlap = [&](int k, int m, bool k_asleep) {
      const double *a = box + kStride * k, *b = box + kStride * m;
      if ((b[2] <= a[3]) & (a[2] <= b[3]) & (b[4] <= a[5]) & (a[4] <= b[5]) &
              !(k_asleep && state.bodies[order[m]].asleep) &&
          !(grouped && apart(order[k], order[m]))) {
        pairs.emplace_back(order[k], order[m]);  // both ways: each body's points against the other's solid
        pairs.emplace_back(order[m], order[k]);
      }
    };
    int next_from = -1;  // in the next strip: the first box that may still reach the current one
    for (int k = begin; k < end; ++k) {
      const double* a = box + kStride * k;
      const bool asleep = state.bodies[order[k]].asleep;
      const int strip_end = static_cast<int>(a[7]);
      for (int m = k + 1; m < strip_end && box[kStride * m] <= a[1]; ++m) overlap(k, m, asleep);
      if (strip_end == n || box[kStride * strip_end + 6] != a[6] + 1.0) continue;
      // Boxes are at most `width` long: one starting before lo − width ends before lo.
      if (next_from < strip_end) next_from = strip_end;
      const int next_end = static_cast<int>(box[kStride * strip_end + 7]);
      while (next_from < next_end && box[kStride * next_from] < a[0] - width) ++next_from;
      for (int m = next_from; m < next_end && box[kStride * m] <= a[1]; ++m) {
        if (a[0] <= box[kStride * m + 1]) overlap(k, m, asleep);
      }
    }
  });
  std::vector<std::pair<int, int>>& all = sc.unsorted_directions;
  if (parts == 1) {
    all.swap(sc.parts[0].directions);
  } else {
    all.clear();
    for (int k = 0; k < parts; ++k) all.insert(all.end(), sc.parts[k].directions.begin(), sc.parts[k].directions.end());
  }
  sortDirections(n, all, sc.direction_starts, sc.directions);
}

}  // namespace rigid_body_sim::core
