// A Pinocchio model rebuilt from the plain joint list scripts/pin_model_dump.py writes of a
// file its own parsers loaded (buildModelFromUrdf, buildModelFromMJCF): the `pin` wheel ships
// no urdfdom headers to parse URDF in C++. Shared by benches/peers/pin_models.cpp (instruction
// counts, issue 35), odeint_frontier.cpp (the frontier's spatial trees, issue 39) and
// spatial_reference.cpp (their extended-precision reference).
//
// One joint per line: type parent R(9, rows) p(3) mass lever(3) I(9, rows) [axis(3)], the
// parent a 0-based line index (-1: the universe). Gravity is left at Pinocchio's default.
#pragma once
#include <pinocchio/multibody.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

inline pinocchio::Model load_pin_dump(const std::string& file) {
  using namespace pinocchio;
  Model model;
  std::ifstream in(file);
  if (!in) { std::fprintf(stderr, "cannot read %s\n", file.c_str()); std::exit(2); }
  std::string line;
  std::vector<JointIndex> ids;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string kind;
    int parent;
    double x[25], axis[3] = {0, 0, 0};
    s >> kind >> parent;
    for (double& v : x) s >> v;
    for (double& v : axis) s >> v;
    Eigen::Matrix3d R, I;
    R << x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8];
    I << x[16], x[17], x[18], x[19], x[20], x[21], x[22], x[23], x[24];
    SE3 M(R, Eigen::Vector3d(x[9], x[10], x[11]));
    JointIndex p = parent < 0 ? 0 : ids[parent];
    std::string name = "j" + std::to_string(ids.size());
    JointIndex j;
    if (kind == "RX") j = model.addJoint(p, JointModelRX(), M, name);
    else if (kind == "RY") j = model.addJoint(p, JointModelRY(), M, name);
    else if (kind == "RZ") j = model.addJoint(p, JointModelRZ(), M, name);
    else if (kind == "PX") j = model.addJoint(p, JointModelPX(), M, name);
    else if (kind == "PY") j = model.addJoint(p, JointModelPY(), M, name);
    else if (kind == "PZ") j = model.addJoint(p, JointModelPZ(), M, name);
    else if (kind == "FreeFlyer") j = model.addJoint(p, JointModelFreeFlyer(), M, name);
    else if (kind == "Spherical") j = model.addJoint(p, JointModelSpherical(), M, name);
    else if (kind == "RevoluteUnaligned")
      j = model.addJoint(p, JointModelRevoluteUnaligned(Eigen::Vector3d(axis[0], axis[1], axis[2])), M, name);
    else { std::fprintf(stderr, "unknown joint %s\n", kind.c_str()); std::exit(2); }
    model.appendBodyToJoint(j, Inertia(x[12], Eigen::Vector3d(x[13], x[14], x[15]), I), SE3::Identity());
    ids.push_back(j);
  }
  return model;
}

// Whether joint 1 (the first after the universe) is a free flyer: the one joint with nq ≠ nv
// these harnesses take; every other joint must have one coordinate (q̇ = v).
inline bool free_root(const pinocchio::Model& m) {
  for (pinocchio::JointIndex j = 1; j < pinocchio::JointIndex(m.njoints); ++j) {
    const bool ff = m.joints[j].shortname() == "JointModelFreeFlyer";
    if (ff && j != 1) { std::fprintf(stderr, "a free flyer below the root is not handled\n"); std::exit(2); }
    if (!ff && (m.joints[j].nq() != 1 || m.joints[j].nv() != 1)) {
      std::fprintf(stderr, "joint %zu: only free flyers at the root and one-coordinate joints\n", size_t(j));
      std::exit(2);
    }
  }
  return m.njoints > 1 && m.joints[1].shortname() == "JointModelFreeFlyer";
}

// q̇ of y = (q, v) (nq + nv numbers) into dq (nq): a free flyer at the root has q = (p, quaternion
// x, y, z, w) and v = (velocity, ω) both in its own frame (Pinocchio's convention), so ṗ = R v and
// (ẇ, ė) = ½ (−e·ω, w ω + e × ω); every other coordinate has q̇ = v.
template <class S, class Y, class D> void config_rate(bool free, int nq, const Y& y, D& dq) {
  int qi = 0, vi = 0;
  if (free) {
    const S x = y[3], yy = y[4], z = y[5], w = y[6];
    const S vx = y[nq + 0], vy = y[nq + 1], vz = y[nq + 2], wx = y[nq + 3], wy = y[nq + 4], wz = y[nq + 5];
    // R of the unit quaternion (w; x, y, z), rows
    const S r00 = 1 - 2 * (yy * yy + z * z), r01 = 2 * (x * yy - w * z), r02 = 2 * (x * z + w * yy);
    const S r10 = 2 * (x * yy + w * z), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (yy * z - w * x);
    const S r20 = 2 * (x * z - w * yy), r21 = 2 * (yy * z + w * x), r22 = 1 - 2 * (x * x + yy * yy);
    dq[0] = r00 * vx + r01 * vy + r02 * vz;
    dq[1] = r10 * vx + r11 * vy + r12 * vz;
    dq[2] = r20 * vx + r21 * vy + r22 * vz;
    dq[3] = (w * wx + yy * wz - z * wy) / 2;
    dq[4] = (w * wy + z * wx - x * wz) / 2;
    dq[5] = (w * wz + x * wy - yy * wx) / 2;
    dq[6] = -(x * wx + yy * wy + z * wz) / 2;
    qi = 7;
    vi = 6;
  }
  for (; qi < nq; ++qi, ++vi) dq[qi] = y[nq + vi];
}

// The state (q, v) in the frontier's common form, which every tool's end state is compared in:
// for a free root, position, attitude quaternion scalar first (η ≥ 0), joint angles, the base's
// velocity in the ground (R v), ω in the body, joint rates; a fixed base is (q, v) as it is.
template <class S, class Y> std::vector<S> common_form(bool free, int nq, int nv, const Y& y) {
  std::vector<S> out(y.begin(), y.begin() + nq + nv);
  if (!free) return out;
  const S x = y[3], yy = y[4], z = y[5], w = y[6];
  const S sign = w < 0 ? S(-1) : S(1);
  out[3] = sign * w; out[4] = sign * x; out[5] = sign * yy; out[6] = sign * z;
  std::vector<S> dq(nq);
  config_rate<S>(free, nq, y, dq);  // ṗ = R v
  out[nq + 0] = dq[0]; out[nq + 1] = dq[1]; out[nq + 2] = dq[2];
  return out;
}
