#pragma once
// ODE's library-wide initialisation, done once per process before the first world exists.
namespace stride::sim {
void ensure_ode_initialised();
}
