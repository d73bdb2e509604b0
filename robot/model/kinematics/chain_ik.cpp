#include "robot/model/kinematics/chain_ik.hpp"

#include <algorithm>

#include "robot/model/kinematics/dls_ik.hpp"
#include "robot/model/kinematics/nao_joint_map.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"
#include "robot/model/urdf_loader.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {

ChainIkResult chain_ik(NaoChain c, const Eigen::Isometry3d& target, const std::string& urdf) {
  const auto ids = chain_joints(c);
  ChainIkResult out;
  out.q.resize(ids.size());
  if (c == NaoChain::LLeg || c == NaoChain::RLeg) {
    const LegIkResult r = leg_ik(c == NaoChain::LLeg ? Side::Left : Side::Right, target);
    std::copy(r.q.begin(), r.q.end(), out.q.begin());
    out.reachable = r.reachable;
    out.residual = r.position_error;
    return out;
  }
  const RobotModel m = load_urdf(urdf);
  const NaoJointMap map = make_nao_joint_map(m);
  const char* link = c == NaoChain::Head ? "Head" : c == NaoChain::LArm ? "LHand" : "RHand";
  const Eigen::Vector3d point =
      c == NaoChain::Head ? Eigen::Vector3d::Zero() : Eigen::Vector3d(nao::kHandOffsetX, 0, 0);
  JointVector jq = zero_joints(m);
  DlsIkWorkspace work;
  DlsIkOptions opt;
  opt.damping = 1e-2;
  const DlsIkResult r = dls_ik(m, m.link_index(link), target, jq, work, opt, point);
  for (size_t i = 0; i < ids.size(); ++i) out.q[i] = jq[map.model_index[hal::index(ids[i])]];
  out.reachable = r.converged;
  out.residual = r.error;
  return out;
}

}  // namespace stride::model
