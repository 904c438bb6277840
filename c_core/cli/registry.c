/* dclaw's table of law subcommands (the build generates dclaw_commands.h
   from cli/cmd_<law>.c) and its lookup; used by main (dclaw.c) and by
   dclaw plot (plot.c). */
#include "cli.h"
#include "dclaw_commands.h"
#include <string.h>

#define N_COMMANDS (sizeof dc_cli_commands / sizeof dc_cli_commands[0])

const dc_cli_command *dc_cli_find(const char *law)
{
  for (size_t i = 0; i < N_COMMANDS; i++)
    if (!strcmp(law, dc_cli_commands[i]->name)) return dc_cli_commands[i];
  return NULL;
}

void dc_cli_list(FILE *out)
{
  for (size_t i = 0; i < N_COMMANDS; i++)
    fprintf(out, "  %-16s %s\n", dc_cli_commands[i]->name, dc_cli_commands[i]->summary);
}
