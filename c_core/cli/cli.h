/* Shared pieces of the dclaw command-line tool. */
#ifndef DC_CLI_H
#define DC_CLI_H

typedef struct {
  const char *name;
  int (*run)(int argc, char **argv);  /* argv[0] is the law name */
  const char *summary;
} dc_cli_command;

/* Key-value options: --key value. Unknown keys are an error. */
typedef struct {
  const char *key;     /* without the leading -- */
  const char *help;
  double value;        /* default, overwritten by the command line */
  int given;           /* set when the key was on the command line */
} dc_cli_option;

/* Parses argv into opts (NULL-key terminated). Prints help for --help and
   returns 1; prints an error naming the key and returns 2 on bad input;
   returns 0 on success. */
int dc_cli_parse(int argc, char **argv, dc_cli_option *opts, const char *usage_line);

/* Value of a named option (the name must exist). */
double dc_cli_get(const dc_cli_option *opts, const char *key);
int dc_cli_given(const dc_cli_option *opts, const char *key);

int cmd_hertz_elliptic(int argc, char **argv);
int cmd_jkr_elliptic(int argc, char **argv);
int cmd_gw_rough(int argc, char **argv);

#endif
