#pragma once
// Parameters of the thesis' walking pattern (Sec. 3.3-3.6), named as in Table 4.3.
#include <optional>
#include <string>
#include <vector>

namespace stride::walking {

// Minimum and maximum forward waist speed within one step (Fig. 3.7, Eq. 3.1).
struct SpeedLevel {
  double V_min = 0.0;  // m/s, at the middle of the single support
  double V_max = 0.0;  // m/s, during the double support
};

struct PatternParameters {
  double T_stride = 0.5;  // s, walking period: two steps (Table 4.3)
  double tau_dsp = 0.01;  // double-support ratio of a step (Table 4.3)
  double A_l = 0.001;     // m, lateral swing amplitude of the waist (Eq. 3.9)
  double z_min = 0.323;   // m, lowest torso-origin height, in double support (Eq. 3.10)
  double z_max = 0.325;   // m, highest torso-origin height, mid single support (Eq. 3.10)
  double d_0 = 0.050;     // m, lateral distance of each foot from the walking line
  double H_foot = 0.026;  // m, maximum elevation of the swing foot (Eq. 3.11)
  SpeedLevel rhythmic{0.18, 0.19};
  // Intermediate speed levels from rest up to `rhythmic` (Fig. 3.7 left: V_min2/V_max2,
  // V_min1/V_max1, ...) and from `rhythmic` down to rest. Each list of n levels means n + 1
  // polynomial steps (Eq. 3.5, Eq. 3.6).
  std::vector<SpeedLevel> development;
  std::vector<SpeedLevel> decay;
  int steps = 60;         // waist steps of T_step; the feet make steps + 1 swings (Sec. 4.3.4.2)
  double gravity = 9.81;  // m/s^2 (Eq. 3.16)
  // Constant torso-origin height of the conventional bent-knee pattern (Table 4.5).
  double z_conventional = 0.318;

  double T_step() const { return 0.5 * T_stride; }
  // Start and end of the double support within a step (Eq. 3.1).
  double T_s() const { return 0.5 * T_step() * (1.0 - tau_dsp); }
  double T_d() const { return T_step() * tau_dsp + T_s(); }
  // Lateral frequency: one sway per stride, half the vertical frequency (Characteristic C).
  double omega() const;
  int development_steps() const { return static_cast<int>(development.size()) + 1; }
  int decay_steps() const { return static_cast<int>(decay.size()) + 1; }
  int rhythmic_steps() const { return steps - development_steps() - decay_steps(); }
};

// Highest torso-origin height above the sole: hip offset + thigh + tibia + foot height, i.e. the
// waist of Sec. 3.2 taken as the torso origin (thesis' z_max = 0.332 m fits under 0.3331 m).
double max_waist_height();

// `n - 1` levels evenly between rest and `target`: the intermediate levels of n steps.
std::vector<SpeedLevel> linear_levels(const SpeedLevel& target, int n);

// First problem found, as one line naming the parameter; nullopt when the set is usable.
std::optional<std::string> validation_error(const PatternParameters& p);
// Throws stride::Error with validation_error()'s message.
void validate(const PatternParameters& p);

// Table 4.3 with the waist heights and lateral amplitudes of the three speeds of Sec. 4.3.4.2
// ("slow", "medium", "fast"), the plotting sets of Fig. 3.14 ("fig3.14") and Fig. 3.16
// ("fig3.16"), and the 20 s energy walks of Table 4.4 ("table4.4-5", "-10", "-15", "-20" cm/s).
// Throws stride::Error for an unknown name.
PatternParameters preset(const std::string& name);
std::vector<std::string> preset_names();

// Sets one parameter by its Table 4.3 name (T_stride, tau_dsp, A_l, A_s, z_min, z_max, d_0,
// H_foot, V_min, V_max, steps, development_steps, decay_steps, development_levels,
// decay_levels, gravity, z_conventional). Levels are written "vmin:vmax,vmin:vmax". Throws
// stride::Error naming the parameter for an unknown name or unparsable value; range checks are
// validate()'s job.
void set_parameter(PatternParameters& p, const std::string& name, const std::string& value);
std::vector<std::string> parameter_names();

}  // namespace stride::walking
