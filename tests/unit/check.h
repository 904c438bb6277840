/* Minimal assertion helpers for the c_core unit tests: each CHECK prints a
   line on failure and counts it; check_summary() prints "N passed, N failed"
   and gives the exit code. */
#ifndef DC_CHECK_H
#define DC_CHECK_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int check_passed_, check_failed_;

static int check_true_(int ok, const char *what, const char *file, int line)
{
  if (ok) { check_passed_++; return 1; }
  check_failed_++;
  printf("FAIL %s:%d: %s\n", file, line, what);
  return 0;
}

/* |got - want| <= tol * max(|want|, tiny); NaN or Inf always fails. */
static int check_rel_(double got, double want, double tol, const char *what,
                      const char *file, int line)
{
  double scale = fabs(want) > 1e-300 ? fabs(want) : 1e-300;
  double err = fabs(got - want) / scale;
  int ok = isfinite(got) && err <= tol;
  if (ok) { check_passed_++; return 1; }
  check_failed_++;
  printf("FAIL %s:%d: %s: got %.17g want %.17g rel.err %.3g > %.3g\n",
         file, line, what, got, want, err, tol);
  return 0;
}

static int check_abs_(double got, double want, double tol, const char *what,
                      const char *file, int line)
{
  double err = fabs(got - want);
  int ok = isfinite(got) && err <= tol;
  if (ok) { check_passed_++; return 1; }
  check_failed_++;
  printf("FAIL %s:%d: %s: got %.17g want %.17g abs.err %.3g > %.3g\n",
         file, line, what, got, want, err, tol);
  return 0;
}

#define CHECK(cond) check_true_((cond) != 0, #cond, __FILE__, __LINE__)
#define CHECK_REL(got, want, tol, what) check_rel_((got), (want), (tol), (what), __FILE__, __LINE__)
#define CHECK_ABS(got, want, tol, what) check_abs_((got), (want), (tol), (what), __FILE__, __LINE__)

/* Uniform [0, 1) from a xorshift64 state (fixed seeds: reproducible sweeps). */
static double check_uniform(unsigned long long *x)
{
  *x ^= *x << 13; *x ^= *x >> 7; *x ^= *x << 17;
  return (double)(*x >> 11) * 0x1.0p-53;
}

static int check_summary(const char *suite)
{
  printf("%s: %d passed, %d failed\n", suite, check_passed_, check_failed_);
  return check_failed_ ? 1 : 0;
}

/* Reads one comma-separated row of up to n numbers; returns how many. */
static int check_read_row(FILE *f, double *v, int n)
{
  char line[2048];
  if (!fgets(line, sizeof line, f)) return 0;
  int k = 0;
  for (char *p = strtok(line, ",\n"); p && k < n; p = strtok(NULL, ",\n")) v[k++] = strtod(p, NULL);
  return k;
}

/* Opens a committed reference table (path relative to tests/reference). */
static FILE *check_open_reference(const char *name)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/%s", DC_REFERENCE_DIR, name);
  FILE *f = fopen(path, "r");
  if (!f) { check_failed_++; printf("FAIL cannot open reference table %s\n", path); }
  return f;
}
#endif
