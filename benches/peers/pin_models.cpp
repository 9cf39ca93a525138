// Pinocchio C++ harness for benches/models.rs (issue 35, item 4): one of the imported models of
// examples/models/ as Pinocchio's own parsers load it (buildModelFromUrdf, buildModelFromMJCF;
// the `pin` wheel ships no urdfdom headers, so scripts/pin_model_dump.py writes the parsed
// model's joints, placements and inertias, checked there against the parsed model, and this
// harness rebuilds it with addJoint/appendBodyToJoint), then one algorithm `iters` times on 64
// pre-generated states (q = integrate(neutral, random v)), for instruction counts under
// callgrind: two runs with different `iters`, difference of the totals / difference of iters.
//
// Usage: pin_models algo dump iters   (algo: rnea aba crba rnea_derivatives aba_derivatives)
// Built and run by benches/peers/icount_models.sh (header-only).
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include "../../scripts/peers/cpp/pin_dump.hpp"
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
using namespace pinocchio;

static Model load(const std::string& file) { return load_pin_dump(file); }

int main(int argc, char** argv) {
  if (argc < 4) { std::fprintf(stderr, "usage: pin_models algo file iters\n"); return 2; }
  std::string algo = argv[1], file = argv[2];
  long iters = std::atol(argv[3]);
  Model model = load(file);
  model.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  Data data(model);
  const int NS = 64;
  std::vector<Eigen::VectorXd> q(NS), v(NS), a(NS);
  for (int i = 0; i < NS; ++i) {
    q[i] = integrate(model, neutral(model), Eigen::VectorXd::Random(model.nv));
    v[i] = Eigen::VectorXd::Random(model.nv);
    a[i] = Eigen::VectorXd::Random(model.nv);
  }
  double sink = 0;
  for (long k = 0; k < iters; ++k) {
    int s = k % NS;
    if (algo == "rnea") sink += rnea(model, data, q[s], v[s], a[s])[0];
    else if (algo == "aba") sink += aba(model, data, q[s], v[s], a[s])[0];
    else if (algo == "crba") sink += crba(model, data, q[s])(0, 0);
    else if (algo == "rnea_derivatives") {
      computeRNEADerivatives(model, data, q[s], v[s], a[s]);
      sink += data.dtau_dq(0, 0) + data.dtau_dv(0, 0);
    } else if (algo == "aba_derivatives") {
      computeABADerivatives(model, data, q[s], v[s], a[s]);
      sink += data.ddq_dq(0, 0) + data.ddq_dv(0, 0) + data.Minv(0, 0);
    } else { std::fprintf(stderr, "unknown algorithm %s\n", algo.c_str()); return 2; }
  }
  std::printf("%s %s nq=%d nv=%d iters=%ld sink=%g\n", algo.c_str(), file.c_str(), model.nq, model.nv, iters, sink);
  return 0;
}
