#include "console/cli/subcommand.hpp"

#include <ostream>

#include "robot/app/robot_main.hpp"

namespace stride::cli {

// Each subcommand lives in its own file; declare it here and add one line to the table.
int run_main(Args args, std::ostream& out, std::ostream& err);
int balance_main(Args args, std::ostream& out, std::ostream& err);
int kin_main(Args args, std::ostream& out, std::ostream& err);
int dyn_main(Args args, std::ostream& out, std::ostream& err);
int pattern_main(Args args, std::ostream& out, std::ostream& err);
int experiment_main(Args args, std::ostream& out, std::ostream& err);
int push_sweep_main(Args args, std::ostream& out, std::ostream& err);
int swing_leg_main(Args args, std::ostream& out, std::ostream& err);
int landing_main(Args args, std::ostream& out, std::ostream& err);
int converge_main(Args args, std::ostream& out, std::ostream& err);
int robot_main(Args args, std::ostream& out, std::ostream& err);
int lola_main(Args args, std::ostream& out, std::ostream& err);
int sweep_main(Args args, std::ostream& out, std::ostream& err);
int tune_main(Args args, std::ostream& out, std::ostream& err);
int view_main(Args args, std::ostream& out, std::ostream& err);
int identify_main(Args args, std::ostream& out, std::ostream& err);
std::string_view identify_summary();

namespace {

constexpr const char* kRunUsage =
    "run <scene> --seconds S [--seed N] [--physics a=v,b=w] [--report out.json] [--log file] "
    "[--snapshot f.png] "
    "[--video dir] [--view follow|front|side|top|<camera>] [--fps N] [--lola <socket> "
    "[--robot name] [--realtime] [--lola-wait S] | --lola-packets [--robot name]] [--debug "
    "addr:port [--token-file f] [--log-dir d]] | run <scene> "
    "--ensemble N [--seconds S] [--seed N] [--heading-spread rad] [--position-spread m] "
    "[--jobs N]: headless simulation (--lola: that robot is served over a LoLA socket); "
    "--physics: physics settings over the scene's, e.g. engine=mujoco; --debug: served to "
    "consoles in real time until --seconds or Ctrl-C, paused until the first console "
    "connects; --ensemble: N perturbed starts, the walk's spread and fall count";

constexpr const char* kExperimentUsage =
    "experiment posture|knee-energy|kalman|fastest|arm-swing|gains|push|position-push|"
    "push-recovery|landing-control [--seeds N] [--jobs N] [--out dir] [--scenes dir] "
    "[--sweeps dir] [--resume] [--quiet] [--no-plots] [--set Module.field=value ...] "
    "[--physics a=v,b=w] [--cases a,b] [--only column=a,b ...] [--through-lola | "
    "--lola-packets]: the experiments, the sweep "
    "files "
    "scenes/experiments/<name>.sweep.xml (--jobs: walks at once, default all hardware "
    "threads; --set: a module parameter in every walk; --cases: posture cases to run, e.g. "
    "hip or none_fast; --only: runs with these levels, e.g. seed=1,2)";

}  // namespace

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"balance",
       "balance classify|ankle-boundaries|closed-loop|hip|combined|lqr [--x0 m --v0 m/s ...] "
       "[--json] [--csv f] [--plots dir]: Ch. 7 balance analysis",
       balance_main},
      {"push-sweep",
       "push-sweep --scene S --strategy ankle|hip|combined|lqr --impulses a:b:step --directions "
       "0,180 [--duration s] [--jobs N] [--csv f] [--json]: Ch. 7 push experiments",
       push_sweep_main},
      {"run", kRunUsage, run_main},
      {"robot", kRobotUsage, robot_main},
      {"lola", kLolaUsage, lola_main},
      {"converge",
       "converge <scene> [--settings \"iterations=20 solver=exact ...\"] [--reference S] "
       "[--starts N] [--seconds S] [--tolerance r] [--lost-tolerance n] [--jobs N] [--out dir] "
       "[--no-plots]: walk outcomes over solver settings, each over perturbed starts; the "
       "cheapest setting agreeing with the reference",
       converge_main},
      {"kin", "kin fk|ik|com --chain C --q \"...\" | --pose \"x y z r p y\": NAO kinematics",
       kin_main},
      {"swing-leg",
       "swing-leg planar-step|planar-track|3d-step|3d-track [--controller adaptive|pd|both] "
       "[--seconds S] [--dt s] [--csv dir] [--plots dir] | swing-leg ode-track [--scene f] "
       "[--seconds S] [--preset P]: Ch. 5 adaptive vs PD swing-leg control",
       swing_leg_main},
      {"landing",
       "landing [--scene f] [--speed m/s] [--depth m] [--seconds S] [--kz N/m] [--bz N s/m] [--csv "
       "f]: "
       "Ch. 6 "
       "landing impact, position control vs the impedance law",
       landing_main},
      {"dyn", "dyn params --model planar|3d [--json]: swing-leg parameter vector (App. C)",
       dyn_main},
      {"pattern",
       "pattern [--preset P] [--set name=value ...] [--conventional] --csv out.csv [--plots dir]: "
       "walking pattern (Ch. 3) offline",
       pattern_main},
      {"sweep",
       "sweep <file.xml> [--jobs N] [--out dir] [--resume] [--overwrite] [--quiet] [--seeds N] "
       "[--scenes dir] [--set target=value ...] [--only column=a,b ...] [--no-plots] [--mpi] "
       "[--through-lola | --lola-packets]: the runs of a sweep file (scenes x factors x seeds) on "
       "local worker processes, or on MPI ranks under mpirun/srun; one CSV row per run, tallies "
       "printed (--through-lola: each run's controller a started `stride robot` on LoLA, "
       "lockstep; --lola-packets: in process through LoLA's packets)",
       sweep_main},
      {"tune",
       "tune <file.xml> [--jobs N] [--out dir] [--resume] [--overwrite] [--quiet] [--set "
       "target=value ...] [--physics a=v,b=w] [--no-plots] [--mpi]: a search (pagmo's pso_gen) "
       "over a tuning file's parameters, each generation one sweep on local workers or MPI "
       "ranks; the best candidate against the thesis' values on the held-out walks only",
       tune_main},
      {"identify", identify_summary(), identify_main},
      {"view",
       "view <scene> | --connect host:port | --log <file> [--scene S] [--listen addr:port] "
       "[--token-file f] [--seconds S]: the live view in a browser (3D scene, plots, data, "
       "console); prints its URL first (--listen port 0: any free port)",
       view_main},
      {"experiment", kExperimentUsage, experiment_main},
  };
  return table;
}

}  // namespace stride::cli
