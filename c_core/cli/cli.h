/* Shared pieces of the dclaw command-line tool. */
#ifndef DC_CLI_H
#define DC_CLI_H

#include <stdio.h>

typedef struct {
  const char *name;
  int (*run)(int argc, char **argv);  /* argv[0] is the law name */
  const char *summary;
} dc_cli_command;

/* Defines subcommand law's entry; cli/cmd_<law>.c must hold exactly one, and
   the build lists it in dclaw's table (generated dclaw_commands.h). */
#define DC_CLI_COMMAND(law, run, summary) \
  extern const dc_cli_command dc_cli_cmd_##law; \
  const dc_cli_command dc_cli_cmd_##law = {#law, run, summary}

/* The subcommand of a law, NULL if there is none (registry.c). */
const dc_cli_command *dc_cli_find(const char *law);

/* Prints each law's name and summary, one per line (registry.c). */
void dc_cli_list(FILE *out);

/* dclaw plot (plot.c): runs law subcommands and draws their tables with
   python3 and matplotlib (plot.py); argv[0] is "plot". */
#define DC_CLI_PLOT_USAGE \
  "plot --png FILE [--y force|area|stiffness|tangential|creep|all] [--csv FILE] -- <law> [--key value ...] [-- <law> ...]"
int dc_cli_plot(int argc, char **argv);

/* Key-value options: --key value. Unknown keys are an error. */
typedef struct {
  const char *key;     /* without the leading -- */
  const char *help;
  double value;        /* default, overwritten by the command line */
  const char *text;    /* the value as given on the command line, NULL if not given */
} dc_cli_option;

/* Largest accepted --n (number of rows). */
#define DC_CLI_N_MAX 1000000
#define DC_CLI_STR_(x) #x
#define DC_CLI_STR(x) DC_CLI_STR_(x)
#define DC_CLI_N_HELP "number of overlaps, an integer from 1 to " DC_CLI_STR(DC_CLI_N_MAX)

/* Parses argv into opts (NULL-key terminated). Prints help for --help and
   returns 1; prints an error naming the key and returns 2 on bad input
   (unknown key, missing or empty value, not wholly a finite number);
   returns 0 on success. */
int dc_cli_parse(int argc, char **argv, dc_cli_option *opts, const char *usage_line);

/* Value of a named option (the name must exist). */
double dc_cli_get(const dc_cli_option *opts, const char *key);
int dc_cli_given(const dc_cli_option *opts, const char *key);

/* Reads option key as a count in [1, DC_CLI_N_MAX] into *n; else prints an
   error naming --key and returns 2. */
int dc_cli_count(const char *law, const dc_cli_option *opts, const char *key, int *n);

/* Whether the options keys[0..n-1] hold whole numbers (settings given by
   number); else prints an error naming the first that does not and
   returns 2. */
int dc_cli_whole(const char *law, const dc_cli_option *opts, const char *const *keys, int n);

/* Overlap i of n evenly spaced from d0 to d1 (d0 if n == 1); finite for finite ends. */
double dc_cli_range(double d0, double d1, int i, int n);

/* Prints the n values v as one CSV row and returns 0. If one is not finite,
   prints nothing to stdout but an error naming that column (columns is the
   CSV header) and the keys behind it (given keys with extreme values, else
   all given keys), and returns 2. */
int dc_cli_row(const char *law, const dc_cli_option *opts, const char *columns, int n, const double *v);

#endif
