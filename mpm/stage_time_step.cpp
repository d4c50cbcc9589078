#include <string>

#include "mpm/stages.hpp"

namespace ffp::mpm {

// Δt_{n+1} = C · h_min / (c_p + |v|)_max   (CFL; h_min follows a moving mesh)
void update_time_step(Simulation& s) {
  s.dt_limit_s = cfl_time_step_limit(s, s.stressed_signal);  // formed by update_stresses right before, if it was
  s.stressed_signal.clear();
  if (s.settings.fixed_dt_s) {
    if (*s.settings.fixed_dt_s > s.dt_limit_s)
      throw StepFailure("the fixed time step " + std::to_string(*s.settings.fixed_dt_s) + " s exceeds the CFL limit " +
                        std::to_string(s.dt_limit_s) + " s at t = " + std::to_string(s.time_s) + " s");
    s.dt_next_s = *s.settings.fixed_dt_s;
  } else {
    s.dt_next_s = s.settings.courant * s.dt_limit_s;
  }
}

}  // namespace ffp::mpm
