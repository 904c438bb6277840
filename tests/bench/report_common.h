/* Shared pieces of the speed-versus-error report programs
   (tests/bench/bench_report_*.c, run by tests/bench/report.sh): a timer,
   best-of-repetitions timing of a loop, the error accumulator and the CSV
   row every program prints.

   CSV (one header line from report_header, then one row per law and scene):
     family,scene,law,exact,ns_per_call,error,error_rms,metric,note
   exact: 1 for the scene's exact law (its error is that of its evaluation:
   0 where it is the reference itself). error: the scene's error metric
   (metric says which) against the exact law of the same physics on the same
   scene, computed by the program. error_rms: the root mean square of the
   same quantity over the scene's samples. Text fields hold no commas or
   quotes. */
#ifndef DC_REPORT_COMMON_H
#define DC_REPORT_COMMON_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* Timing repetitions (best kept); the environment variable
   DC_REPORT_REPS overrides (the smoke test uses 1). */
static int report_reps(void)
{
  const char *s = getenv("DC_REPORT_REPS");
  const int n = s ? atoi(s) : 0;
  return n > 0 ? n : 5;
}

/* CPU time of this thread [s]: a process that is descheduled on the shared
   machine does not count the time it waits. */
static double report_now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

static volatile double report_sink;

/* Sets ns to the time per call of `body`, run for i = 0 .. n-1: the
   passes over the n inputs are doubled until one repetition takes 2 ms
   (clock overhead below 1e-4), then the best of report_reps() repetitions
   is kept. body adds what it computes to the double `acc`, so that nothing
   is optimised away. */
#define REPORT_TIME(ns, n, body)                                          \
  do {                                                                    \
    long passes_ = 1;                                                     \
    double best_ = 1e300;                                                 \
    for (int rep_ = 0; rep_ < report_reps(); rep_++) {                    \
      double acc = 0.0, dt_;                                              \
      for (;;) {                                                          \
        const double t0_ = report_now();                                  \
        for (long p_ = 0; p_ < passes_; p_++)                             \
          for (int i = 0; i < (n); i++) { body; }                         \
        dt_ = report_now() - t0_;                                         \
        if (rep_ > 0 || dt_ >= 2e-3 || passes_ >= (1L << 24)) break;     \
        passes_ *= 2;                                                     \
      }                                                                   \
      report_sink = acc;                                                  \
      if (dt_ < best_) best_ = dt_;                                       \
    }                                                                     \
    (ns) = 1e9 * best_ / ((double)passes_ * (n));                         \
  } while (0)

/* Largest and root-mean-square of a set of errors. */
typedef struct {
  double max, sum2;
  long n;
} report_err;

static void report_err_add(report_err *e, double x)
{
  x = fabs(x);
  if (isnan(x) || isnan(e->max)) e->max = NAN;   /* a NaN error stays and shows */
  else if (x > e->max) e->max = x;
  e->sum2 += x * x;
  e->n++;
}

static double report_err_rms(const report_err *e) { return e->n ? sqrt(e->sum2 / e->n) : 0.0; }

static void report_header(void) { printf("family,scene,law,exact,ns_per_call,error,error_rms,metric,note\n"); }

static void report_row(const char *family, const char *scene, const char *law, int exact, double ns,
                       const report_err *e, const char *metric, const char *note)
{
  printf("%s,%s,%s,%d,%.4g,%.4g,%.4g,%s,%s\n", family, scene, law, exact, ns, e->max, report_err_rms(e), metric,
         note ? note : "");
  fflush(stdout);
}

/* Uniform [0, 1) from a xorshift64 state (fixed seeds: the same scene on
   every run). */
static double report_uniform(unsigned long long *x)
{
  *x ^= *x << 13;
  *x ^= *x >> 7;
  *x ^= *x << 17;
  return (double)(*x >> 11) * 0x1.0p-53;
}

#endif
