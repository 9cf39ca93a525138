/* MuJoCo through its C API on the work–precision frontier (issue 39): the model of an MJCF
 * file (written by frontier_compiled.py from frontier_common.chain_xml, or the free body of
 * frontier_mujoco.py), NSTEP calls of mj_step with timestep T/NSTEP and the integrator given,
 * from the initial state of the problem:
 *
 *   chain     qpos = (0.7, 0.1, …, 0.1), qvel = 0          state printed: (qpos, qvel)
 *   rigid     free joint, qvel[3:6] = ω(0) = (1, 0, 0.5)   state printed: qvel[3:6] (body ω)
 *   pendulum  qpos[0] = THETA0                             state printed: (qpos[0], qvel[0])
 *
 * usage:  mujoco_frontier XML euler|rk4|implicitfast NSTEP T chain|rigid|pendulum [THETA0]
 * prints one JSON line {"seconds", "repeats", "state"}: the median wall time of one whole run
 * (mj_resetData, the initial state, NSTEP × mj_step), with the timing rule of
 * examples/frontier/timing.rs (repeats while the total stays under 0.5 s, at most 21).
 * Model compilation is setup (untimed). Single-threaded (no thread pool is created). */
#include <mujoco/mujoco.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static void setup(const mjModel* m, mjData* d, const char* kind, double theta0) {
  mj_resetData(m, d);
  if (!strcmp(kind, "chain")) {
    for (int i = 0; i < m->nq; ++i) d->qpos[i] = i ? 0.1 : 0.7;
  } else if (!strcmp(kind, "rigid")) {
    d->qvel[3] = 1.0; d->qvel[4] = 0.0; d->qvel[5] = 0.5;
  } else {
    d->qpos[0] = theta0;
  }
}

int main(int argc, char** argv) {
  if (argc < 6) {
    fprintf(stderr, "usage: mujoco_frontier XML euler|rk4|implicitfast NSTEP T chain|rigid|pendulum [THETA0]\n");
    return 2;
  }
  char err[1000] = "";
  mjModel* m = mj_loadXML(argv[1], NULL, err, sizeof err);
  if (!m) { fprintf(stderr, "%s: %s\n", argv[1], err); return 2; }
  const char* integ = argv[2];
  if (!strcmp(integ, "euler")) m->opt.integrator = mjINT_EULER;
  else if (!strcmp(integ, "rk4")) m->opt.integrator = mjINT_RK4;
  else if (!strcmp(integ, "implicitfast")) m->opt.integrator = mjINT_IMPLICITFAST;
  else { fprintf(stderr, "unknown integrator %s\n", integ); return 2; }
  long nstep = atol(argv[3]);
  double t_end = atof(argv[4]);
  const char* kind = argv[5];
  double theta0 = argc > 6 ? atof(argv[6]) : 0.0;
  if (nstep < 1 || !(t_end > 0)) { fprintf(stderr, "NSTEP ≥ 1 and T > 0 needed\n"); return 2; }
  m->opt.timestep = t_end / nstep;
  mjData* d = mj_makeData(m);

  double times[21], total = 0;
  int reps = 0;
  do {
    double t0 = now();
    setup(m, d, kind, theta0);
    for (long k = 0; k < nstep; ++k) mj_step(m, d);
    times[reps] = now() - t0;
    total += times[reps];
    ++reps;
  } while (reps < 21 && total + times[reps - 1] < 0.5);
  qsort(times, reps, sizeof(double), cmp);
  double med = reps % 2 ? times[reps / 2] : 0.5 * (times[reps / 2 - 1] + times[reps / 2]);

  printf("{\"seconds\": %.6e, \"repeats\": %d, \"state\": [", med, reps);
  if (!strcmp(kind, "rigid")) {
    printf("%.17g, %.17g, %.17g", d->qvel[3], d->qvel[4], d->qvel[5]);
  } else if (!strcmp(kind, "pendulum")) {
    printf("%.17g, %.17g", d->qpos[0], d->qvel[0]);
  } else {
    for (int i = 0; i < m->nq; ++i) printf("%s%.17g", i ? ", " : "", d->qpos[i]);
    for (int i = 0; i < m->nv; ++i) printf(", %.17g", d->qvel[i]);
  }
  printf("]}\n");
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
