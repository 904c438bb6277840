/* dclaw plot: runs one or more law subcommands, collects their CSV tables
   and hands them to the plotting script (plot.py, python3 with matplotlib),
   which draws force, area and stiffness against overlap (the tangential
   force against displacement, the creep force against creepage) into a PNG. */
#include "cli.h"
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* The interpreter and the script, from the environment or the build. */
static const char *setting(const char *env, const char *built)
{
  const char *v = getenv(env);
  return v && *v ? v : built;
}

static void usage(FILE *out)
{
  fprintf(out,
          "usage: dclaw " DC_CLI_PLOT_USAGE "\n"
          "Draws the tables the laws print (as dclaw <law> [--key value ...] would) against the overlap delta\n"
          "(cmd_tangential: the displacement u, kalker: the creepage xi) into a PNG: one curve per law and\n"
          "quantity column, the legend naming the law and its keys; several laws share the axes.\n"
          "  --png FILE  the PNG to write\n"
          "  --y Q       force, area, stiffness, tangential (Ft) or creep (Fx) (one panel), or all (a panel\n"
          "              per quantity the tables have, the default)\n"
          "  --csv FILE  also write the plotted series: label,column,<delta, u or xi>,value\n"
          "Runs $DCLAW_PYTHON (default %s), which needs matplotlib (Debian package\n"
          "python3-matplotlib), on $DCLAW_PLOT_SCRIPT (default %s).\n",
          DC_PLOT_PYTHON, DC_PLOT_SCRIPT);
}

/* Whether args (a law and its keys) ask for help. */
static int asks_help(int argc, char **argv)
{
  for (int i = 1; i < argc; i++)
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) return 1;
  return 0;
}

/* The end of the law segment starting at argv[s]: the next "--" or argc. */
static int segment_end(int argc, char **argv, int s)
{
  while (s < argc && strcmp(argv[s], "--")) s++;
  return s;
}

/* Runs the law segments of argv[first..argc) with their stdout into the file
   fd, each table after a line "# <law> <keys>". Returns the first nonzero
   status of a law (which has printed its error), else 0. */
static int run_laws(int argc, char **argv, int first, int fd)
{
  fflush(stdout);
  const int saved = dup(STDOUT_FILENO);
  dup2(fd, STDOUT_FILENO);
  int st = 0;
  for (int s = first, end; s < argc && !st; s = end + 1) {
    end = segment_end(argc, argv, s);
    printf("#");
    for (int k = s; k < end; k++) printf(" %s", argv[k]);
    printf("\n");
    st = dc_cli_find(argv[s])->run(end - s, argv + s);
  }
  fflush(stdout);
  dup2(saved, STDOUT_FILENO);
  close(saved);
  return st;
}

int dc_cli_plot(int argc, char **argv)
{
  const char *png = NULL, *y = "all", *csv = NULL;
  int i = 1;
  for (; i < argc && strcmp(argv[i], "--"); i += 2) {
    if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      usage(stdout);
      return 0;
    }
    const char **value = !strcmp(argv[i], "--png") ? &png : !strcmp(argv[i], "--y") ? &y
                         : !strcmp(argv[i], "--csv") ? &csv : NULL;
    if (!value) {
      fprintf(stderr, "dclaw plot: unknown option '%s' (see dclaw plot --help)\n", argv[i]);
      return 2;
    }
    if (i + 1 >= argc || !strcmp(argv[i + 1], "--") || !*argv[i + 1]) {
      fprintf(stderr, "dclaw plot: %s needs a value\n", argv[i]);
      return 2;
    }
    *value = argv[i + 1];
  }
  if (!png) {
    fprintf(stderr, "dclaw plot: --png FILE is missing\nusage: dclaw " DC_CLI_PLOT_USAGE "\n");
    return 2;
  }
  if (strcmp(y, "force") && strcmp(y, "area") && strcmp(y, "stiffness") && strcmp(y, "tangential") &&
      strcmp(y, "creep") && strcmp(y, "all")) {
    fprintf(stderr, "dclaw plot: --y '%s': must be force, area, stiffness, tangential, creep or all\n", y);
    return 2;
  }
  if (i >= argc) {
    fprintf(stderr, "dclaw plot: no law given\nusage: dclaw " DC_CLI_PLOT_USAGE "\n");
    return 2;
  }
  /* every law is checked before any runs; a law's --help shows its keys */
  const int first = i + 1;
  for (int s = first, end; s <= argc; s = end + 1) {
    end = segment_end(argc, argv, s);
    if (end == s) {
      fprintf(stderr, "dclaw plot: no law after '--'\n");
      return 2;
    }
    const dc_cli_command *law = dc_cli_find(argv[s]);
    if (!law) {
      fprintf(stderr, "dclaw plot: unknown law '%s' (dclaw --help lists the laws)\n", argv[s]);
      return 2;
    }
    if (asks_help(end - s, argv + s)) return law->run(end - s, argv + s);
  }

  const char *python = setting("DCLAW_PYTHON", DC_PLOT_PYTHON), *script = setting("DCLAW_PLOT_SCRIPT", DC_PLOT_SCRIPT);
  if (access(script, R_OK)) {
    fprintf(stderr, "dclaw plot: cannot read the plotting script %s: %s (set DCLAW_PLOT_SCRIPT to c_core/cli/plot.py)\n",
            script, strerror(errno));
    return 2;
  }
  FILE *tables = tmpfile();
  if (!tables) {
    fprintf(stderr, "dclaw plot: cannot create a temporary file: %s\n", strerror(errno));
    return 2;
  }
  int st = run_laws(argc, argv, first, fileno(tables));
  if (st) {
    fclose(tables);
    return st;
  }
  lseek(fileno(tables), 0, SEEK_SET);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(fileno(tables), STDIN_FILENO);
    char *args[] = {(char *)python, (char *)script, "--png", (char *)png, "--y", (char *)y,
                    csv ? "--csv" : NULL, (char *)csv, NULL};
    execvp(python, args);
    fprintf(stderr, "dclaw plot: cannot run %s: %s (needs python3 with matplotlib: Debian packages python3 and "
            "python3-matplotlib; or set DCLAW_PYTHON)\n", python, strerror(errno));
    _exit(2);
  }
  fclose(tables);
  int status;
  if (pid < 0 || waitpid(pid, &status, 0) < 0) {
    fprintf(stderr, "dclaw plot: cannot run %s: %s\n", python, strerror(errno));
    return 2;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  fprintf(stderr, "dclaw plot: %s %s ended by signal %d\n", python, script, WTERMSIG(status));
  return 2;
}
