#pragma once
// Electrical energy of the knee actuators (thesis Sec. 4.3.4.3): W = U * sum(I_j) * dt over one
// walk (Eq. 4.16), its mean over repeated walks (Eq. 4.17), and the thesis' standard deviation.
#include <span>
#include <vector>

namespace stride::experiments {

inline constexpr double kNominalArmatureVoltage = 21.6;  // V, as in Sec. 4.3.4.3

// Eq. 4.16 with a constant voltage and sampling interval: U * (sum of the samples) * dt.
double electrical_work(std::span<const double> current, double voltage, double dt);

// Eq. 4.17: arithmetic mean of the walks' energies (0 for none).
double mean_work(std::span<const double> works);

// Population standard deviation, sigma = sqrt(1/N sum (x_i - mean)^2), as the thesis' footnote 4.
double population_std(std::span<const double> values);

// Saving of `ours` relative to `baseline` in percent: 100 * (baseline - ours) / baseline.
double saving_percent(double ours, double baseline);

}  // namespace stride::experiments
