#pragma once
// The control loop's scheduling. On the NAO a LoLA client runs its loop under SCHED_FIFO so that
// nothing else on the robot (the debug server, logging, other processes) can delay a frame.
#include <string>
#include <vector>

namespace stride {

// Parses a SCHED_FIFO priority (an integer 1..99) given to `flag`; else a one-line Error.
int parse_realtime_priority(const std::string& text, const std::string& flag);

// Runs the calling thread under SCHED_FIFO at `priority`; a one-line Error naming `who` and why
// when the system refuses (it needs root, CAP_SYS_NICE or an rtprio limit).
void set_realtime_priority(int priority, const std::string& who);

// Runs the calling thread on `cpus` only (CPU numbers); threads and processes it starts inherit
// the set. A one-line Error naming `who` for a CPU this machine does not have.
void set_cpu_affinity(const std::vector<int>& cpus, const std::string& who);
// Every CPU of this machine but `cpu` (where helpers go when the loop has `cpu` to itself).
std::vector<int> cpus_except(int cpu);

// Returns the calling thread to the normal time-sharing policy: a thread started by a real-time
// thread inherits its policy, and a helper thread must never compete with the loop.
void set_normal_priority();

}  // namespace stride
