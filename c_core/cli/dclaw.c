/* dclaw: evaluate a c_core force law for given inputs and print CSV.
   Usage: dclaw <law> [--key value ...]; dclaw --help lists the laws;
   dclaw plot draws laws' tables into a PNG (plot.c).
   Each law's subcommand lives in cli/cmd_<law>.c (DC_CLI_COMMAND); their
   table and its lookup are registry.c's. */
#include "cli.h"
#include <stdio.h>
#include <string.h>

/* Prints the usage line and the laws with their summaries. */
static void usage(FILE *out)
{
  fprintf(out, "usage: dclaw <law> [--key value ...]   (dclaw <law> --help for its keys)\n"
               "       dclaw " DC_CLI_PLOT_USAGE "   (dclaw plot --help)\nlaws:\n");
  dc_cli_list(out);
}

int main(int argc, char **argv)
{
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    usage(argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (!strcmp(argv[1], "plot")) return dc_cli_plot(argc - 1, argv + 1);
  const dc_cli_command *law = dc_cli_find(argv[1]);
  if (law) return law->run(argc - 1, argv + 1);
  fprintf(stderr, "dclaw: unknown law '%s'\n", argv[1]);
  usage(stderr);
  return 2;
}
