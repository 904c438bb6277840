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

/* The one reader of the committed reference tables (tests/reference/<name>.csv)
   for every unit test: check_read_row, and check_read_tagged_row for tables
   whose first column is text. Both read the next row, skipping blank lines
   and comment lines (first character '#'); split it at commas; and convert
   fields with strtod, each field as a whole (surrounding blanks allowed).
   They return how many numeric fields were read, at most n, stopping at
   the first field that is not a number: a row of column names gives 0, as
   does the end of the file, and a short row fewer than n. Tables with a
   row of column names: read it with one call first. A line longer than the
   buffer is a failure (counted) and is skipped. */
static int check_read_fields_(FILE *f, char *tag, size_t ntag, double *v, int n)
{
  char line[4096];
  for (;;) {
    if (!fgets(line, sizeof line, f)) return 0;
    const size_t len = strlen(line);
    if (len + 1 == sizeof line && line[len - 1] != '\n' && !feof(f)) {
      check_failed_++;
      printf("FAIL reference table row longer than %d characters\n", (int)sizeof line - 2);
      int c;
      while ((c = fgetc(f)) != EOF && c != '\n') {}
      continue;
    }
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '#' || *p == '\n' || *p == '\r' || *p == '\0') continue;
    break;
  }
  char *p = line;
  if (tag) {
    /* first field: text */
    size_t k = 0;
    while (*p == ' ' || *p == '\t') p++;
    while (*p && *p != ',' && *p != '\n' && *p != '\r') {
      if (k + 1 < ntag) tag[k++] = *p;
      p++;
    }
    while (k > 0 && (tag[k - 1] == ' ' || tag[k - 1] == '\t')) k--;
    if (ntag > 0) tag[k] = '\0';
    if (*p != ',') return 0;
    p++;
  }
  int k = 0;
  while (k < n) {
    char *end;
    const double x = strtod(p, &end);
    if (end == p) break;
    while (*end == ' ' || *end == '\t' || *end == '\r') end++;
    if (*end != ',' && *end != '\n' && *end != '\0') break;
    v[k++] = x;
    if (*end != ',') break;
    p = end + 1;
  }
  return k;
}

/* The next row of numbers (above). */
static int check_read_row(FILE *f, double *v, int n) { return check_read_fields_(f, NULL, 0, v, n); }

/* The next row whose first field is text: that field (truncated to ntag -
   1 characters) in tag, the numbers after it in v (above). */
static int check_read_tagged_row(FILE *f, char *tag, size_t ntag, double *v, int n)
{
  return check_read_fields_(f, tag, ntag, v, n);
}

/* The next row tagged want, rows with other tags skipped; the count of
   numbers read as check_read_tagged_row gives it, 0 at the end. */
static int check_next_tagged_row(FILE *f, const char *want, double *v, int n)
{
  char tag[32];
  int k;
  while ((k = check_read_tagged_row(f, tag, sizeof tag, v, n)) > 0)
    if (!strcmp(tag, want)) return k;
  return 0;
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
