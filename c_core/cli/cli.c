/* Option parsing, ranges and checked CSV rows shared by the dclaw subcommands. */
#include "cli.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int dc_cli_parse(int argc, char **argv, dc_cli_option *opts, const char *usage_line)
{
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      printf("usage: dclaw %s %s\n", argv[0], usage_line);
      for (dc_cli_option *o = opts; o->key; o++)
        printf("  --%-12s %s (default %g)\n", o->key, o->help, o->value);
      printf("A result that is not finite is an error (exit 2) naming the keys behind it.\n");
      return 1;
    }
    if (strncmp(argv[i], "--", 2) != 0) {
      fprintf(stderr, "dclaw %s: expected --key, got '%s'\n", argv[0], argv[i]);
      return 2;
    }
    dc_cli_option *o = opts;
    while (o->key && strcmp(o->key, argv[i] + 2)) o++;
    if (!o->key) {
      fprintf(stderr, "dclaw %s: unknown key '%s' (see --help)\n", argv[0], argv[i]);
      return 2;
    }
    if (i + 1 >= argc) {
      fprintf(stderr, "dclaw %s: --%s needs a value\n", argv[0], o->key);
      return 2;
    }
    const char *s = argv[++i];
    char *end;
    double v = strtod(s, &end);
    if (end == s || isspace((unsigned char)*s) || *end || !isfinite(v)) {
      fprintf(stderr, "dclaw %s: --%s: '%s' is not a finite number\n", argv[0], o->key, s);
      return 2;
    }
    o->value = v;
    o->text = s;
  }
  return 0;
}

/* The option named key, or the terminating entry. */
static const dc_cli_option *find(const dc_cli_option *opts, const char *key)
{
  while (opts->key && strcmp(opts->key, key)) opts++;
  return opts;
}

double dc_cli_get(const dc_cli_option *opts, const char *key) { return find(opts, key)->value; }
int dc_cli_given(const dc_cli_option *opts, const char *key) { return find(opts, key)->text != NULL; }

int dc_cli_count(const char *law, const dc_cli_option *opts, const char *key, int *n)
{
  const dc_cli_option *o = find(opts, key);
  const double v = o->value;
  if (!(v >= 1 && v <= DC_CLI_N_MAX && v == floor(v))) {
    fprintf(stderr, "dclaw %s: --%s %s: must be an integer from 1 to %d\n", law, key, o->text ? o->text : "(default)", DC_CLI_N_MAX);
    return 2;
  }
  *n = (int)v;
  return 0;
}

double dc_cli_range(double d0, double d1, int i, int n)
{
  if (n == 1) return d0;
  const double d = d0 + (d1 - d0) * i / (n - 1), t = (double)i / (n - 1);
  return isfinite(d) ? d : d0 * (1 - t) + d1 * t;  /* the second form cannot overflow */
}

/* Whether a given value is far enough from 1 to overflow or underflow a law. */
static int extreme(double v) { return fabs(v) > 1e100 || (v != 0 && fabs(v) < 1e-100); }

int dc_cli_row(const char *law, const dc_cli_option *opts, const char *columns, int n, const double *v)
{
  int bad = 0;
  while (bad < n && isfinite(v[bad])) bad++;
  if (bad == n) {
    for (int i = 0; i < n; i++) printf(i ? ",%.17g" : "%.17g", v[i]);
    printf("\n");
    return 0;
  }
  const char *col = columns;
  for (int i = 0; i < bad && strchr(col, ','); i++) col = strchr(col, ',') + 1;
  fprintf(stderr, "dclaw %s: %.*s is %g, not finite; from", law, (int)strcspn(col, ","), col, v[bad]);
  int given = 0, any = 0;
  for (const dc_cli_option *o = opts; o->key; o++) {
    given |= o->text != NULL;
    any |= o->text && extreme(o->value);
  }
  for (const dc_cli_option *o = opts; o->key; o++)
    if ((o->text || !given) && (extreme(o->value) || !any)) {
      if (o->text) fprintf(stderr, " --%s %s", o->key, o->text);
      else fprintf(stderr, " --%s %g", o->key, o->value);
    }
  fprintf(stderr, "%s\n", any ? " (too large or too small a value)" : "");
  return 2;
}

int dc_cli_whole(const char *law, const dc_cli_option *opts, const char *const *keys, int n)
{
  for (int i = 0; i < n; i++) {
    const double v = dc_cli_get(opts, keys[i]);
    if (v != floor(v)) {
      fprintf(stderr, "dclaw %s: --%s: %g is not a whole number\n", law, keys[i], v);
      return 2;
    }
  }
  return 0;
}
