// The compiled peer of the work–precision frontier (issue 39): Boost.Odeint's controlled
// Dormand–Prince 5(4) (`runge_kutta_dopri5`), Fehlberg 7(8) (`runge_kutta_fehlberg78`) and
// Bulirsch–Stoer (`bulirsch_stoer`) at rtol = atol = TOL, on
//
//   * the hinge chains of frontier_common.py with Pinocchio's C++ ABA as right-hand side
//     (the model of frontier_pinocchio.py: revolute-y joints, capsule moments, g = 9.81 −z),
//   * the torque-free body (Euler's equations + quaternion), Kepler e = 0.9 and the pendulum
//     at 3 rad with hand-written right-hand sides (Eigen for the body's vector algebra),
//   * the 7-DOF arm of examples/models/arm7.urdf with Pinocchio's C++ ABA on the model its URDF
//     parser made (rebuilt from scripts/pin_model_dump.py's joint list: pin_dump.hpp), from rest
//     at the angles of examples/frontier/problems.rs ARM7_Q0, g = 9.81 −z, t ≤ 1,
//   * the floating quadruped of examples/models/quadruped.urdf the same way (its free flyer's q̇
//     from v by config_rate in pin_dump.hpp), falling and turning for 1 s,
//   * the energy problem (θ₀ = 1 rad, 10⁴ periods, E read every 10 periods through dense
//     output: `make_dense_output` for DP5, `bulirsch_stoer_dense_out` for BS; RKF78 has no
//     dense output in Odeint, so `integrate_times` steps it onto each checkpoint).
//
// usage:  odeint_frontier PROBLEM METHOD TOL [PERIOD|DUMP] (PERIOD: energy-pendulum; DUMP: arm7's
//                                                         or the quadruped's model file, from
//                                                         pin_model_dump.py)
//         odeint_frontier rhs chain-N                     (prints f(y0), for the model check)
// prints one JSON line: {"seconds": median wall time of one whole run, "repeats": …,
// "fevals": …, "steps": …, "state": final state (energy: [max |E − E₀|/E₀])}. The errors are
// measured by frontier_compiled.py against the same references as every other tool.
// Timing rule of examples/frontier/timing.rs: one run, then repeats while the total stays
// under 0.5 s, at most 21 runs; the median. Single-threaded; model building is setup (untimed).
#include <pinocchio/multibody.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <boost/numeric/odeint.hpp>
#include "pin_dump.hpp"
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace ode = boost::numeric::odeint;

// ------------------------------------------------------------------ timing

template <class F> static double median_time(F run, int* repeats) {
  std::vector<double> t;
  double total = 0;
  do {
    auto t0 = std::chrono::steady_clock::now();
    run();
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    t.push_back(s);
    total += s;
  } while (t.size() < 21 && total + t.back() < 0.5);
  *repeats = int(t.size());
  std::sort(t.begin(), t.end());
  size_t n = t.size();
  return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

template <size_t N> static void report(double secs, int reps, long fevals, size_t steps, const std::array<double, N>& x, size_t k = N) {
  std::printf("{\"seconds\": %.6e, \"repeats\": %d, \"fevals\": %ld, \"steps\": %zu, \"state\": [", secs, reps, fevals, steps);
  for (size_t i = 0; i < k; ++i) std::printf("%s%.17g", i ? ", " : "", x[i]);
  std::printf("]}\n");
}

// ------------------------------------------------------------------ the integrators

// One adaptive run of `sys` from x0 over [0, t_end] with METHOD at rtol = atol = tol.
template <class S, class Sys> static size_t integrate(const std::string& method, Sys sys, S& x, double t_end, double tol) {
  const double dt0 = 1e-3 * t_end;
  if (method == "dopri5") return ode::integrate_adaptive(ode::make_controlled(tol, tol, ode::runge_kutta_dopri5<S>()), sys, x, 0.0, t_end, dt0);
  if (method == "rkf78") return ode::integrate_adaptive(ode::make_controlled(tol, tol, ode::runge_kutta_fehlberg78<S>()), sys, x, 0.0, t_end, dt0);
  if (method == "bs") {
    ode::bulirsch_stoer<S> bs(tol, tol);
    return ode::integrate_adaptive(bs, sys, x, 0.0, t_end, dt0);
  }
  std::fprintf(stderr, "unknown method %s (dopri5, rkf78, bs)\n", method.c_str());
  std::exit(2);
}

template <size_t N, class Sys> static void ladder_point(const std::string& method, double tol, Sys sys, const std::array<double, N>& x0, double t_end, long* fev, size_t k = N) {
  std::array<double, N> x = x0;
  size_t steps = 0;
  int reps = 0;
  double secs = median_time([&] { x = x0; *fev = 0; steps = integrate(method, sys, x, t_end, tol); }, &reps);
  report<N>(secs, reps, *fev, steps, x, k);
}

// ------------------------------------------------------------------ hand-written right-hand sides

using S2 = std::array<double, 2>;
using S4 = std::array<double, 4>;
using S7 = std::array<double, 7>;

struct Rigid {  // y = (ω, q), q = (η, ε): Euler's equations and q̇ = ½ q ⊗ (0, ω); I = (1, 2, 3)
  long* fev;
  void operator()(const S7& y, S7& dy, double) const {
    ++*fev;
    const double i1 = 1, i2 = 2, i3 = 3;
    Eigen::Map<const Eigen::Vector3d> w(y.data()), e(y.data() + 4);
    dy[0] = (i2 - i3) * w[1] * w[2] / i1;
    dy[1] = (i3 - i1) * w[2] * w[0] / i2;
    dy[2] = (i1 - i2) * w[0] * w[1] / i3;
    dy[3] = -0.5 * e.dot(w);
    Eigen::Map<Eigen::Vector3d>(dy.data() + 4) = 0.5 * (y[3] * w + e.cross(w));
  }
};

struct Kepler {  // r̈ = −r/|r|³
  long* fev;
  void operator()(const S4& y, S4& dy, double) const {
    ++*fev;
    double r2 = y[0] * y[0] + y[1] * y[1], r3 = r2 * std::sqrt(r2);
    dy[0] = y[2]; dy[1] = y[3]; dy[2] = -y[0] / r3; dy[3] = -y[1] / r3;
  }
};

struct Pendulum {  // θ̈ = −sin θ
  long* fev;
  void operator()(const S2& y, S2& dy, double) const { ++*fev; dy[0] = y[1]; dy[1] = -std::sin(y[0]); }
};

// ------------------------------------------------------------------ the chain (Pinocchio ABA)

static pinocchio::Model chain_model(int n) {
  // frontier_common.capsule_inertia: a cylinder of length h and two hemispherical caps
  const double r = 0.02, h = 0.3, m = 1.0, pi = M_PI;
  double vol = pi * r * r * h + 4.0 / 3.0 * pi * r * r * r, mc = m * pi * r * r * h / vol, ms = m - mc;
  double axial = mc * r * r / 2 + ms * 2 * r * r / 5;
  double perp = mc * (h * h / 12 + r * r / 4) + ms * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8);
  pinocchio::Model model;
  pinocchio::JointIndex parent = 0;
  for (int i = 0; i < n; ++i) {
    pinocchio::SE3 place(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i ? -h : 0.0));
    parent = model.addJoint(parent, pinocchio::JointModelRY(), place, "j" + std::to_string(i));
    model.appendBodyToJoint(parent, pinocchio::Inertia(m, Eigen::Vector3d(0, 0, -h / 2), Eigen::Vector3d(perp, perp, axial).asDiagonal()),
                            pinocchio::SE3::Identity());
  }
  model.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  return model;
}

template <size_t N> struct Chain {  // y = (q, v): q̇ = v, v̇ = ABA(q, v, τ = 0)
  const pinocchio::Model* model;
  pinocchio::Data* data;
  const Eigen::VectorXd* tau;
  long* fev;
  void operator()(const std::array<double, N>& y, std::array<double, N>& dy, double) const {
    ++*fev;
    constexpr int n = int(N / 2);
    Eigen::Map<const Eigen::Matrix<double, n, 1>> q(y.data()), v(y.data() + n);
    pinocchio::aba(*model, *data, q, v, *tau);
    std::copy(y.begin() + n, y.end(), dy.begin());
    Eigen::Map<Eigen::Matrix<double, n, 1>>(dy.data() + n) = data->ddq;
  }
};

template <size_t N> static void chain(const std::string& method, double tol, bool rhs_only) {
  constexpr int n = int(N / 2);
  pinocchio::Model model = chain_model(n);
  pinocchio::Data data(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(n);
  long fev = 0;
  Chain<N> sys{&model, &data, &tau, &fev};
  std::array<double, N> y0{};
  for (int i = 0; i < n; ++i) y0[i] = i ? 0.1 : 0.7;
  if (rhs_only) {
    std::array<double, N> dy{};
    sys(y0, dy, 0.0);
    report<N>(0.0, 0, fev, 0, dy);
    return;
  }
  ladder_point<N>(method, tol, sys, y0, 1.0, &fev);
}

// ------------------------------------------------------------------ the arm (Pinocchio ABA)

static void arm7(const std::string& method, double tol, const char* dump) {
  pinocchio::Model model = load_pin_dump(dump);
  model.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  if (model.nq != 7 || model.nv != 7) { std::fprintf(stderr, "arm7: expected 7 joints\n"); std::exit(2); }
  pinocchio::Data data(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(7);
  long fev = 0;
  Chain<14> sys{&model, &data, &tau, &fev};
  const std::array<double, 14> y0{0.3, 1.2, -0.5, -0.8, 0.4, 0.6, -0.2};
  ladder_point<14>(method, tol, sys, y0, 1.0, &fev);
}

// ------------------------------------------------------------------ the quadruped (free root)

// Chain's shape with nq ≠ nv (the free joint's quaternion): dynamic-size maps here, so that Chain
// keeps the fixed-size ones, the peer's fastest form on the chains and the arm
template <size_t N> struct Floating {  // y = (q, v): q̇ = config_rate(q, v), v̇ = ABA(q, v, τ = 0)
  const pinocchio::Model* model;
  pinocchio::Data* data;
  const Eigen::VectorXd* tau;
  long* fev;
  void operator()(const std::array<double, N>& y, std::array<double, N>& dy, double) const {
    ++*fev;
    const int nq = model->nq, nv = model->nv;
    Eigen::Map<const Eigen::VectorXd> q(y.data(), nq), v(y.data() + nq, nv);
    pinocchio::aba(*model, *data, q, v, *tau);
    config_rate<double>(true, nq, y, dy);
    Eigen::Map<Eigen::VectorXd>(dy.data() + nq, nv) = data->ddq;
  }
};

// The quadruped of examples/models/quadruped.urdf: its trunk on a free flyer from the placement
// 0.45 m up, turning at ω = (0.3, 0.5, 1.0) rad/s with the legs bent (examples/frontier/problems.rs
// QUADRUPED_*), falling for 1 s; the end state printed in the common form of pin_dump.hpp.
static void quadruped(const std::string& method, double tol, const char* dump) {
  pinocchio::Model model = load_pin_dump(dump);
  model.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  if (!free_root(model) || model.nq != 19 || model.nv != 18) { std::fprintf(stderr, "quadruped: expected a free root and 12 joints\n"); std::exit(2); }
  pinocchio::Data data(model);
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(18);
  long fev = 0;
  Floating<37> sys{&model, &data, &tau, &fev};
  const std::array<double, 37> y0{0, 0, 0, 0, 0, 0, 1, 0.2, 0.7, -1.4, -0.2, 0.7, -1.4, 0.2, -0.7, 1.4, -0.2, -0.7, 1.4,
                                  0, 0, 0, 0.3, 0.5, 1.0};
  std::array<double, 37> x = y0;
  size_t steps = 0;
  int reps = 0;
  double secs = median_time([&] { x = y0; fev = 0; steps = integrate(method, sys, x, 1.0, tol); }, &reps);
  const std::vector<double> c = common_form<double>(true, 19, 18, x);
  std::array<double, 37> out{};
  std::copy(c.begin(), c.end(), out.begin());
  report<37>(secs, reps, fev, steps, out);
}

// ------------------------------------------------------------------ energy over 10⁴ periods

static void energy(const std::string& method, double tol, double period) {
  const double theta0 = 1.0, e0 = 1 - std::cos(theta0);
  std::vector<double> times;
  for (int k = 0; k <= 1000; ++k) times.push_back(std::min(period * 10 * k, period * 10000));
  long fev = 0;
  Pendulum sys{&fev};
  double worst = 0;
  size_t steps = 0;
  auto observe = [&](const S2& y, double) {
    worst = std::max(worst, std::abs(0.5 * y[1] * y[1] + 1 - std::cos(y[0]) - e0) / e0);
  };
  const double dt0 = 1e-3;
  auto run = [&] {
    S2 y{theta0, 0.0};
    worst = 0; fev = 0;
    if (method == "dopri5")
      steps = ode::integrate_times(ode::make_dense_output(tol, tol, ode::runge_kutta_dopri5<S2>()), sys, y, times.begin(), times.end(), dt0, observe);
    else if (method == "rkf78")
      steps = ode::integrate_times(ode::make_controlled(tol, tol, ode::runge_kutta_fehlberg78<S2>()), sys, y, times.begin(), times.end(), dt0, observe);
    else {
      ode::bulirsch_stoer_dense_out<S2> bs(tol, tol);
      steps = ode::integrate_times(bs, sys, y, times.begin(), times.end(), dt0, observe);
    }
  };
  int reps = 0;
  double secs = median_time(run, &reps);
  std::array<double, 1> out{worst};
  report<1>(secs, reps, fev, steps, out);
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: odeint_frontier PROBLEM METHOD TOL [PERIOD] | odeint_frontier rhs chain-N\n");
    return 2;
  }
  bool rhs_only = std::strcmp(argv[1], "rhs") == 0;
  std::string problem = rhs_only ? argv[2] : argv[1];
  std::string method = rhs_only ? "" : argv[2];
  double tol = argc > 3 ? std::atof(argv[3]) : 0.0;
  if (!rhs_only && !(tol > 0 && tol < 1)) {
    std::fprintf(stderr, "TOL must be in (0, 1), got %s\n", argc > 3 ? argv[3] : "nothing");
    return 2;
  }
  long fev = 0;
  if (problem == "rigid-body") {
    ladder_point<7>(method, tol, Rigid{&fev}, S7{1.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0}, 20.0, &fev);
  } else if (problem == "kepler-e0.9") {
    const double e = 0.9;  // periapsis of a = 1: r = 1 − e, speed √((1 + e)/(1 − e))
    ladder_point<4>(method, tol, Kepler{&fev}, S4{1 - e, 0.0, 0.0, std::sqrt((1 + e) / (1 - e))}, 20.0, &fev);
  } else if (problem == "pendulum") {
    ladder_point<2>(method, tol, Pendulum{&fev}, S2{3.0, 0.0}, 10.0, &fev);
  } else if (problem == "energy-pendulum") {
    if (argc < 5) { std::fprintf(stderr, "energy-pendulum needs PERIOD\n"); return 2; }
    energy(method, tol, std::atof(argv[4]));
  } else if (problem == "arm7") {
    if (argc < 5) { std::fprintf(stderr, "arm7 needs DUMP (scripts/pin_model_dump.py of arm7.urdf)\n"); return 2; }
    arm7(method, tol, argv[4]);
  } else if (problem == "quadruped") {
    if (argc < 5) { std::fprintf(stderr, "quadruped needs DUMP (scripts/pin_model_dump.py of quadruped.urdf)\n"); return 2; }
    quadruped(method, tol, argv[4]);
  } else if (problem == "chain-1") chain<2>(method, tol, rhs_only);
  else if (problem == "chain-2") chain<4>(method, tol, rhs_only);
  else if (problem == "chain-6") chain<12>(method, tol, rhs_only);
  else if (problem == "chain-12") chain<24>(method, tol, rhs_only);
  else if (problem == "chain-30") chain<60>(method, tol, rhs_only);
  else {
    std::fprintf(stderr, "unknown problem %s\n", problem.c_str());
    return 2;
  }
  return 0;
}
