// Simulation entry points: initialise a graph, advance it, broadcast events.
//
// init_root follows SOFA's initRoot (spec/framework.md §3.4); animate calls
// the root's animation loop, which implements the step pipeline.
#pragma once

#include "core/node.h"

namespace sinew {

// Initialises the whole graph: default animation loop if missing, init
// top-down, bwd_init bottom-up, project and propagate at t = 0, store reset
// state. Returns false when an error was reported during init.
bool init_root(Node& root);

// Initialises what was added to an initialised graph (components and nodes
// whose init never ran: added between steps, or under a node activated
// later), in the same order as init_root: init top-down, bwd_init bottom-up,
// then the new nodes' subtrees are projected and propagated at the current
// time and their reset states stored. The loop calls it by itself before the
// mechanical stages of a step when the structure changed. Returns false when
// an error was reported.
bool init_added(Node& root);

// Back to the state stored at init (SOFA's Simulation::reset): time 0, every
// component's reset() top-down (states take their reset positions and
// velocities), then positions and velocities projected and propagated.
void reset_root(Node& root);

// Closes the simulation (SOFA's CleanupVisitor, run when a scene is unloaded): every
// component's cleanup(), top-down in node order. Exporters write their exportAtEnd
// files here. Runs once per root; later calls do nothing.
void cleanup_root(Node& root);

// One step of dt (0: the root's dt).
void animate(Node& root, double dt = 0);

// Broadcasts an event top-down to every listening component, in node order.
void propagate_event(Node& root, Event& e);

// Calls the root's step observers before or after a stage.
void notify_step_observers(Node& root, Stage stage, bool after);
void add_step_observer(Node& root, StepObserver* o);
void remove_step_observer(Node& root, StepObserver* o);

// Projects positions/velocities at time t and propagates them through
// mappings, over the whole graph (used at init and at the end of each step).
void project_and_propagate(Node& root, double t);

}  // namespace sinew
