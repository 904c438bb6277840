/* Option parsing shared by the dclaw subcommands. */
#include "cli.h"
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
    char *end;
    double v = strtod(argv[++i], &end);
    if (*end || !isfinite(v)) {
      fprintf(stderr, "dclaw %s: --%s: '%s' is not a finite number\n", argv[0], o->key, argv[i]);
      return 2;
    }
    o->value = v;
    o->given = 1;
  }
  return 0;
}

static const dc_cli_option *find(const dc_cli_option *opts, const char *key)
{
  while (opts->key && strcmp(opts->key, key)) opts++;
  return opts;
}

double dc_cli_get(const dc_cli_option *opts, const char *key) { return find(opts, key)->value; }
int dc_cli_given(const dc_cli_option *opts, const char *key) { return find(opts, key)->given; }
