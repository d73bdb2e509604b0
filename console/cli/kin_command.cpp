// `stride kin fk|ik|com ...`: NAO forward/inverse kinematics and centre of mass from the shell.
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/json_writer.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"
#include "robot/model/kinematics/chain_ik.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/kinematics/nao_joint_map.hpp"
#include "robot/model/urdf_loader.hpp"

namespace stride::cli {
namespace {

using namespace stride::model;

constexpr const char* kUsage =
    "usage: stride kin fk --chain head|larm|rarm|lleg|rleg --q \"angles\" [--json]\n"
    "       stride kin ik --chain <chain> --pose \"x y z roll pitch yaw\" [--json]\n"
    "       stride kin com --q \"25 angles (LoLA order)\" | \"Name=value ...\" [--urdf file] "
    "[--json]";

std::vector<double> numbers(const std::string& text, const std::string& name, size_t expected) {
  std::istringstream in(text);
  std::vector<double> v;
  std::string word;
  while (in >> word) {
    try {
      v.push_back(parse_number(word, "stride kin: " + name));
    } catch (const Error& e) {
      throw UsageError(e.what());
    }
  }
  if (v.size() != expected)
    throw UsageError("stride kin: " + name + ": expected " + std::to_string(expected) +
                     " numbers, got " + std::to_string(v.size()));
  return v;
}

NaoChain chain_option(ArgumentReader& a) {
  const std::string name = a.text("--chain");
  const auto c = chain_from_name(name);
  if (!c)
    throw UsageError("stride kin: --chain: " + quote(name) +
                     " is not head, larm, rarm, lleg or rleg");
  return *c;
}

// Fixed micro-units (um, urad) so that rounding noise never shows, and no "-0".
std::string fmt(double x) {
  std::ostringstream o;
  o << std::fixed << std::setprecision(6) << x;
  std::string t = o.str();
  return t.find_first_not_of("-0.") == std::string::npos && t[0] == '-' ? t.substr(1) : t;
}

Eigen::Vector3d roll_pitch_yaw(const Eigen::Matrix3d& r) {  // R = Rz(yaw) Ry(pitch) Rx(roll)
  return {std::atan2(r(2, 1), r(2, 2)), std::asin(std::clamp(-r(2, 0), -1.0, 1.0)),
          std::atan2(r(1, 0), r(0, 0))};
}

Eigen::Isometry3d pose_from(const std::vector<double>& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  t.linear() = (Eigen::AngleAxisd(p[5], Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(p[4], Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(p[3], Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  return t;
}

void print_pose(std::ostream& out, const Eigen::Isometry3d& t, bool json) {
  const Eigen::Vector3d p = t.translation(), r = roll_pitch_yaw(t.linear());
  if (json) {
    JsonWriter j(JsonWriter::Style::Spaced);
    j.begin_object().key("position").numbers(p).key("rpy").numbers(r).end_object();
    out << j.str() << "\n";
  } else {
    out << "position (m):      " << fmt(p.x()) << " " << fmt(p.y()) << " " << fmt(p.z()) << "\n"
        << "roll pitch yaw:    " << fmt(r.x()) << " " << fmt(r.y()) << " " << fmt(r.z()) << "\n";
  }
}

std::string default_urdf() {
  return data_file("scenes/robots/nao/nao.urdf");
}

int fk(Args args, std::ostream& out) {
  ArgumentReader a(args, "kin");
  a.only({"--chain", "--q", "--json"});
  const NaoChain c = chain_option(a);
  const auto q = numbers(a.text("--q"), "--q", chain_joints(c).size());
  const bool json = a.flag("--json");
  a.finish();
  print_pose(out, chain_fk(c, q), json);
  return 0;
}

int ik(Args args, std::ostream& out) {
  ArgumentReader a(args, "kin");
  a.only({"--chain", "--pose", "--urdf", "--json"});
  const NaoChain c = chain_option(a);
  const Eigen::Isometry3d target = pose_from(numbers(a.text("--pose"), "--pose", 6));
  const std::string urdf = a.text_or("--urdf", default_urdf());
  const bool json = a.flag("--json");
  a.finish();
  const auto ids = chain_joints(c);
  const ChainIkResult r = chain_ik(c, target, urdf);
  const std::vector<double>& q = r.q;
  const bool reachable = r.reachable;
  const double residual = r.residual;
  if (json) {
    JsonWriter j(JsonWriter::Style::Spaced);
    j.begin_object().field("reachable", reachable).field("residual", residual);
    j.key("q").begin_object();
    for (size_t i = 0; i < ids.size(); ++i) j.field(hal::name(ids[i]), q[i]);
    out << j.end_object().end_object().str() << "\n";
    return 0;
  }
  for (size_t i = 0; i < ids.size(); ++i)
    out << std::left << std::setw(16) << hal::name(ids[i]) << fmt(q[i]) << "\n";
  out << "reachable: " << (reachable ? "yes" : "no") << " (residual " << residual << ")\n";
  return 0;
}

int com(Args args, std::ostream& out) {
  ArgumentReader a(args, "kin");
  a.only({"--q", "--urdf", "--json"});
  const std::string text = a.text("--q");
  const std::string urdf = a.text_or("--urdf", default_urdf());
  const bool json = a.flag("--json");
  a.finish();
  std::array<double, hal::kNumJoints> lola{};
  if (text.find('=') != std::string::npos) {
    std::istringstream in(text);
    std::string pair;
    while (in >> pair) {
      const auto eq = pair.find('=');
      const auto id =
          eq == std::string::npos ? std::nullopt : hal::joint_from_name(pair.substr(0, eq));
      if (!id) throw UsageError("stride kin: --q: " + quote(pair) + " is not JointName=value");
      lola[hal::index(*id)] = numbers(pair.substr(eq + 1), "--q " + pair.substr(0, eq), 1)[0];
    }
  } else {
    const auto v = numbers(text, "--q", hal::kNumJoints);
    std::copy(v.begin(), v.end(), lola.begin());
  }
  const RobotModel m = load_urdf(urdf);
  JointVector q;
  joints_from_lola(m, make_nao_joint_map(m), lola, q);
  std::vector<Eigen::Isometry3d> poses;
  link_poses(m, q, poses);
  const Eigen::Vector3d c = centre_of_mass(m, poses);
  if (json) {
    JsonWriter j(JsonWriter::Style::Spaced);
    j.begin_object().key("com").numbers(c).field("mass", m.total_mass()).end_object();
    out << j.str() << "\n";
  } else
    out << "centre of mass (m, torso frame): " << fmt(c.x()) << " " << fmt(c.y()) << " "
        << fmt(c.z()) << "\ntotal mass (kg): " << fmt(m.total_mass()) << "\n";
  return 0;
}

}  // namespace

int kin_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw UsageError("stride kin: expected fk, ik or com");
    if (args[0] == "--help") {
      out << kUsage << "\n";
      return 0;
    }
    const std::string verb = args[0];
    const Args rest = args.subspan(1);
    out << std::setprecision(9);
    if (verb == "fk") return fk(rest, out);
    if (verb == "ik") return ik(rest, out);
    if (verb == "com") return com(rest, out);
    throw UsageError("stride kin: " + quote(verb) + ": expected fk, ik or com");
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
