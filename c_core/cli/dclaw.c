/* dclaw: evaluate a c_core force law for given inputs and print CSV.
   Usage: dclaw <law> [--key value ...]; dclaw --help lists the laws.
   Each law's subcommand lives in cli/cmd_<law>.c and is listed below. */
#include "cli.h"
#include <stdio.h>
#include <string.h>

static const dc_cli_command commands[] = {
  {"gw_rough", cmd_gw_rough, "GW rough contact: radii, E*, sigma, n_asp, mu, overlaps -> elliptic closed-form and Feng-law force, area, stiffness"},
  {"jkr_elliptic", cmd_jkr_elliptic, "adhesive elliptic JKR (Johnson-Greenwood; classical JKR for R1 = R2): overlaps -> force, area, semi-axes; --summary 1: pull-off force, separation overlap"},
  {"hertz_elliptic", cmd_hertz_elliptic, "elliptic Hertz: radii or curvatures, E*, overlaps -> e^2, gamma, beta, semi-axes, force, area, stiffness"},
};

static void usage(FILE *out)
{
  fprintf(out, "usage: dclaw <law> [--key value ...]   (dclaw <law> --help for its keys)\nlaws:\n");
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    fprintf(out, "  %-16s %s\n", commands[i].name, commands[i].summary);
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
    if (!strcmp(argv[1], commands[i].name)) return commands[i].run(argc - 1, argv + 1);
  fprintf(stderr, "dclaw: unknown law '%s'\n", argv[1]);
  usage(stderr);
  return 2;
}
