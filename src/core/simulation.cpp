#include "rigid_body_sim/core/simulation.h"

#include <utility>

namespace rigid_body_sim::core {

Simulation::Simulation(Model model_in, State state_in)
    : model(std::move(model_in)), state(std::move(state_in)), initial(state) {}

void Simulation::addBody(const PreparedBody& body, const BodyState& start) {
  model.addBody(body);  // in place, unchanged if it throws
  state.bodies.push_back(start);
  initial.bodies.push_back(start);
  workspace = workspace.forEditedModel();  // its caches assumed the old model
}

std::size_t Simulation::removeBody(int i) {
  core::removeBody(model, state, i);    // wakes what may touch it
  core::removeBody(model, initial, i);  // reads the model with body i still in it
  model.removeBody(static_cast<std::size_t>(i));
  contacts.removeBody(i);
  workspace = workspace.forEditedModel();
  return schedule.removeBody(i);
}

void Simulation::place(int i, const BodyState& now) {
  state.bodies.at(static_cast<std::size_t>(i)) = now;
  state.bodies[i].asleep = false;
  state.bodies[i].still_time = 0.0;
  state.contact_impulses.clear();
}

void Simulation::retune(const Tuning& tuning) {
  model = model.retuned(tuning);
  workspace = workspace.forEditedModel();  // the fixed-point cache assumed the old settings
  wakeAll(state);
}

void Simulation::reset(double time) {
  state = initial;
  state.time = time;
  schedule.clear(-1);
}

}  // namespace rigid_body_sim::core
