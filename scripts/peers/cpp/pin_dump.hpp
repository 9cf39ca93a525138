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
