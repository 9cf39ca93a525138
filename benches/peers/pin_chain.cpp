// Pinocchio C++ timing harness for benches/dynamics.rs (headers from the `pin` wheel,
// header-only, -O3 -march=native). Copied from ../shared/peers/cpp/pin_chain.cpp and
// extended with the analytical derivatives (computeRNEADerivatives, computeABADerivatives).
// Same n-link revolute-Y chain as benches/dynamics.rs `pinocchio_chain`. Prints JSON lines.
//
// Build and run: `sh benches/peers/build.sh && ~/.cache/vectrix_pin_chain`
// (or `sh benches/peers/run.sh`, which also runs the matching vectrix benches).
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/model.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>
using namespace pinocchio;

static Model chain(int n, double link = 0.3, double mass = 1.0) {
  Model model;
  JointIndex parent = 0;
  for (int i = 0; i < n; ++i) {
    SE3 placement(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i ? -link : 0.0));
    JointIndex jid = model.addJoint(parent, JointModelRY(), placement, "j" + std::to_string(i));
    Eigen::Matrix3d I = Eigen::Vector3d(mass * link * link / 12, mass * link * link / 12, 1e-4).asDiagonal();
    model.appendBodyToJoint(jid, Inertia(mass, Eigen::Vector3d(0, 0, -link / 2), I), SE3::Identity());
    parent = jid;
  }
  return model;
}

static int reps = 7;

template <class F> static void bench(const char* name, int n, long iters, F f) {
  std::vector<double> s;
  for (int r = 0; r < reps; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    for (long k = 0; k < iters; ++k) f(k);
    auto t1 = std::chrono::steady_clock::now();
    s.push_back(std::chrono::duration<double>(t1 - t0).count() / iters);
  }
  std::sort(s.begin(), s.end());
  std::printf("{\"what\": \"C++ %s\", \"n\": %d, \"median\": %.4e, \"min\": %.4e, \"max\": %.4e, \"number\": %ld}\n",
              name, n, s[s.size() / 2], s[0], s[s.size() - 1], iters);
}

// Usage: vectrix_pin_chain [filter] [iterations-scale] [n]
//   filter: run only algorithms whose name contains it (e.g. "deriv"); default all.
//   iterations-scale: multiplies the iteration counts; below 1 a single repetition (for
//     instruction counts under callgrind: two runs with different scales, difference of the
//     totals over the difference of the iteration counts).
//   n: run only the chain of n links (default: 1, 6, 12, 30).
int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : "";
  double scale = argc > 2 ? std::atof(argv[2]) : 1.0;
  if (scale < 1.0) reps = 1;
  auto want = [&](const char* name) { return std::strstr(name, filter) != nullptr; };
  const int NS = 256;  // pre-generated random states, cycled
  int only = argc > 3 ? std::atoi(argv[3]) : 0;
  for (int n : {1, 6, 12, 30}) {
    if (only && n != only) continue;
    Model model = chain(n);
    Data data(model);
    std::vector<Eigen::VectorXd> q(NS), v(NS), a(NS);
    for (int i = 0; i < NS; ++i) { q[i] = Eigen::VectorXd::Random(n); v[i] = Eigen::VectorXd::Random(n); a[i] = Eigen::VectorXd::Random(n); }
    long iters = std::max(1L, (long)(scale * 2000000 / n));
    long diters = std::max(1L, (long)(scale * 200000 / n));
    double sink = 0;
    if (want("rnea")) bench("rnea", n, iters, [&](long k) { sink += rnea(model, data, q[k % NS], v[k % NS], a[k % NS])[0]; });
    if (want("aba")) bench("aba", n, iters, [&](long k) { sink += aba(model, data, q[k % NS], v[k % NS], a[k % NS])[0]; });
    if (want("crba")) bench("crba", n, iters, [&](long k) { sink += crba(model, data, q[k % NS])(0, 0); });
    if (want("rnea_derivatives"))
      bench("rnea_derivatives", n, diters, [&](long k) {
        computeRNEADerivatives(model, data, q[k % NS], v[k % NS], a[k % NS]);
        sink += data.dtau_dq(0, 0) + data.dtau_dv(0, 0);
      });
    if (want("aba_derivatives"))
      bench("aba_derivatives", n, diters, [&](long k) {
        computeABADerivatives(model, data, q[k % NS], v[k % NS], a[k % NS]);
        sink += data.ddq_dq(0, 0) + data.ddq_dv(0, 0) + data.Minv(0, 0);
      });
    Eigen::VectorXd tau = rnea(model, data, q[0], v[0], a[0]);
    double err = (aba(model, data, q[0], v[0], tau) - a[0]).cwiseAbs().maxCoeff();
    std::printf("{\"what\": \"check aba(rnea(a))-a\", \"n\": %d, \"err\": %.3e, \"sink\": %g}\n", n, err, sink);
  }
}
