// The extended-precision reference end state of a spatial tree of the frontier (issue 39 item
// 4): Pinocchio's ABA on the model its own URDF parser made (rebuilt from
// scripts/pin_model_dump.py's joint list, pin_dump.hpp), cast to IEEE quadruple precision
// (boost::multiprecision::float128, 113-bit significand), integrated by Gragg–Bulirsch–Stoer
// extrapolation with a fixed macro step: in each macro step H the modified midpoint rule (Euler
// start, no smoothing) with n = 2, 4, …, 2K substeps, then Aitken–Neville extrapolation in h² to
// the K-th column (order 2K), K = 12 (the scheme of chain_reference_mp.py). Two runs, STEPS and
// 2·STEPS macro steps over [0, T]; their max-norm difference is printed beside the 2·STEPS end
// state, the one stored. Independent of vectrix: Pinocchio's dynamics, this file's integrator.
//
// Trees of one-coordinate joints, with a free flyer at the root or not (config_rate in
// pin_dump.hpp: Pinocchio's q = (p, x, y, z, w), v in the base's frame); τ = 0, gravity 9.81
// along −z. The end state is printed in the frontier's common form (`common_form`).
//
// The doubles of a model depend on who reads the file (each parser rounds rpy rotations and
// products in its own way, a few ulps apart), and a motion like the arm's amplifies that. So
// SEEDS further runs (at 2·STEPS) start from the same model with every placement, mass, lever
// and inertia number moved by a random relative amount within ±1 ulp (ε = 2⁻⁵²): the largest
// distance of their end states from the stored one, `rounding_spread`, is how far apart two
// equally valid double-precision readings of the file end; no f64 tool that parses the file
// itself can be measured below it.
//
// usage: spatial_reference DUMP T STEPS q0_1,q0_2,… [SEEDS [v0_1,v0_2,…]]   prints one JSON object
// (q0 and v0 in Pinocchio's layout, nq and nv numbers; v0 = 0 when absent)
// Built and run by scripts/peers/spatial_reference.sh.
#include <boost/multiprecision/float128.hpp>
#include <pinocchio/math/multiprecision.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include "pin_dump.hpp"
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using F = boost::multiprecision::float128;
using VecF = Eigen::Matrix<F, Eigen::Dynamic, 1>;

struct Tree {
  pinocchio::ModelTpl<F> model;
  mutable pinocchio::DataTpl<F> data;
  VecF tau;
  bool free;
  mutable long fevals = 0;
  // y = (q, v): ẏ = (q̇(q, v), ABA(q, v, 0))
  VecF operator()(const VecF& y) const {
    ++fevals;
    const int nq = model.nq, nv = model.nv;
    pinocchio::aba(model, data, y.head(nq), y.tail(nv), tau);
    VecF dy(nq + nv);
    config_rate<F>(free, nq, y, dy);
    dy.tail(nv) = data.ddq;
    return dy;
  }
};

static VecF gbs(const Tree& f, VecF y, F t_end, int steps) {
  const int K = 12;
  const F H = t_end / steps;
  std::vector<VecF> T(K);
  for (int s = 0; s < steps; ++s) {
    const VecF f0 = f(y);
    for (int j = 0; j < K; ++j) {
      const int n = 2 * (j + 1);
      const F h = H / n;
      VecF z0 = y, z1 = y + h * f0;
      for (int m = 1; m < n; ++m) {
        VecF z2 = z0 + 2 * h * f(z1);
        z0 = std::move(z1);
        z1 = std::move(z2);
      }
      T[j] = z1;
      // Aitken–Neville: column k of row j from rows j and j−1 of column k−1 (in place, top down)
      for (int k = j - 1; k >= 0; --k) {
        const F r = F(n) / F(2 * (k + 1));
        T[k] = T[k + 1] + (T[k + 1] - T[k]) / (r * r - 1);
      }
    }
    y = T[0];
  }
  return y;
}

// The model with every number of its placements and inertias times (1 + u ε), u uniform in
// [−1, 1] from a linear congruential sequence seeded by `seed`.
static pinocchio::Model perturbed(const pinocchio::Model& m, unsigned long long seed) {
  pinocchio::Model p = m;
  unsigned long long x = seed * 6364136223846793005ULL + 1442695040888963407ULL;
  auto bump = [&](double& v) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = double(x >> 11) / double(1ULL << 53) * 2.0 - 1.0;
    v *= 1.0 + u * 2.220446049250313e-16;
  };
  for (size_t j = 1; j < p.joints.size(); ++j) {
    Eigen::Matrix3d R = p.jointPlacements[j].rotation();
    Eigen::Vector3d t = p.jointPlacements[j].translation();
    for (int k = 0; k < 9; ++k) bump(R.data()[k]);
    for (int k = 0; k < 3; ++k) bump(t[k]);
    p.jointPlacements[j] = pinocchio::SE3(R, t);
    double mass = p.inertias[j].mass();
    Eigen::Vector3d c = p.inertias[j].lever();
    Eigen::Matrix3d I = p.inertias[j].inertia().matrix();
    bump(mass);
    for (int k = 0; k < 3; ++k) bump(c[k]);
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b) { bump(I(a, b)); I(b, a) = I(a, b); }
    p.inertias[j] = pinocchio::Inertia(mass, c, I);
  }
  return p;
}

int main(int argc, char** argv) {
  if (argc < 5) {
    std::fprintf(stderr, "usage: spatial_reference DUMP T STEPS q0_1,q0_2,...\n");
    return 2;
  }
  pinocchio::Model m = load_pin_dump(argv[1]);
  m.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  const bool free = free_root(m);
  const double t_end = std::atof(argv[2]);
  const int steps = std::atoi(argv[3]);
  auto numbers = [](const char* csv) {
    std::vector<double> x;
    std::stringstream ss(csv);
    for (std::string tok; std::getline(ss, tok, ',');) x.push_back(std::stod(tok));
    return x;
  };
  const std::vector<double> q0 = numbers(argv[4]);
  const std::vector<double> v0 = argc > 6 ? numbers(argv[6]) : std::vector<double>(m.nv, 0.0);
  if (!(t_end > 0) || steps < 1 || int(q0.size()) != m.nq || int(v0.size()) != m.nv) {
    std::fprintf(stderr, "need T > 0, STEPS >= 1, %d numbers in q0 and %d in v0\n", m.nq, m.nv);
    return 2;
  }
  Tree f{m.cast<F>(), pinocchio::DataTpl<F>(m.cast<F>()), VecF::Zero(m.nv), free};
  VecF y0(m.nq + m.nv);
  for (int i = 0; i < m.nq; ++i) y0[i] = F(q0[i]);
  for (int i = 0; i < m.nv; ++i) y0[m.nq + i] = F(v0[i]);
  const VecF a = gbs(f, y0, F(t_end), steps);
  const VecF b = gbs(f, y0, F(t_end), 2 * steps);
  const std::vector<F> ca = common_form<F>(free, m.nq, m.nv, a), cb = common_form<F>(free, m.nq, m.nv, b);
  F diff = 0;
  for (size_t i = 0; i < ca.size(); ++i) diff = std::max(diff, F(abs(ca[i] - cb[i])));
  const int seeds = argc > 5 ? std::atoi(argv[5]) : 0;
  F spread = 0;
  for (int k = 1; k <= seeds; ++k) {
    pinocchio::Model pm = perturbed(m, k);
    Tree g{pm.cast<F>(), pinocchio::DataTpl<F>(pm.cast<F>()), VecF::Zero(m.nv), free};
    const std::vector<F> cc = common_form<F>(free, m.nq, m.nv, gbs(g, y0, F(t_end), 2 * steps));
    for (size_t i = 0; i < cc.size(); ++i) spread = std::max(spread, F(abs(cc[i] - cb[i])));
  }
  std::printf("{\"t_end\": %.17g, \"q0\": [", t_end);
  for (size_t i = 0; i < q0.size(); ++i) std::printf("%s%.17g", i ? ", " : "", q0[i]);
  std::printf("], \"v0\": [");
  for (size_t i = 0; i < v0.size(); ++i) std::printf("%s%.17g", i ? ", " : "", v0[i]);
  std::printf("], \"free_root\": %s, \"steps\": [%d, %d], \"K\": 12, \"fevals\": %ld,\n", free ? "true" : "false",
              steps, 2 * steps, f.fevals);
  std::printf(" \"difference\": %s, \"rounding_seeds\": %d, \"rounding_spread\": %s,\n \"state\": [",
              diff.str(3, std::ios_base::scientific).c_str(), seeds, spread.str(3, std::ios_base::scientific).c_str());
  for (size_t i = 0; i < cb.size(); ++i) std::printf("%s%.17g", i ? ", " : "", double(cb[i]));
  std::printf("],\n \"state_36\": [");
  for (size_t i = 0; i < cb.size(); ++i) std::printf("%s\"%s\"", i ? ", " : "", cb[i].str(36).c_str());
  std::printf("]}\n");
  return 0;
}
