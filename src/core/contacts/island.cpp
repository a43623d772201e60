// Islands (docs/physics.md §5.5, §6).
#include "island.h"

#include <algorithm>

#include "step/scratch.h"

namespace rigid_body_sim::core {

void findIslands(const Model& model, const State& state, Workspace& ws) {
  std::vector<int>& parent = ws.scratch->island_root;
  parent.resize(model.bodyCount());
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = static_cast<int>(i);
  const auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Contact& c : ws.contacts) {
    if (c.other < 0 || state.bodies[c.other].asleep || state.bodies[c.body].asleep) continue;
    const int a = find(c.body), b = find(c.other);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root is the island's smallest body
  }
  for (std::size_t i = 0; i < parent.size(); ++i) parent[i] = find(static_cast<int>(i));
}

void groupContactsByIsland(const Model& model, const State& state, Workspace& ws) {
  findIslands(model, state, ws);
  detail::StepScratch& sc = *ws.scratch;
  // A counting sort by island root: islands in root order, each island's
  // contacts in contact order.
  const std::vector<int>& root = sc.island_root;
  std::vector<int>& next = sc.island_of;  // per root: where its island's next contact goes
  next.assign(model.bodyCount(), 0);
  for (const Contact& c : ws.contacts) ++next[islandOf(state, root, c)];
  sc.island_starts.clear();
  int at = 0;
  for (int& slot : next) {
    const int count = slot;
    slot = at;
    if (count > 0) sc.island_starts.push_back(at);
    at += count;
  }
  sc.island_starts.push_back(at);
  sc.island_contacts.resize(ws.contacts.size());
  for (std::size_t k = 0; k < ws.contacts.size(); ++k) {
    sc.island_contacts[next[islandOf(state, root, ws.contacts[k])]++] = static_cast<int>(k);
  }
}

}  // namespace rigid_body_sim::core
