#include "dc/status.h"

const char *dc_status_str(int status)
{
  switch (status) {
  case DC_OK: return "ok";
  case DC_EDOM: return "input outside the domain";
  case DC_ENOCONV: return "iteration did not converge";
  case DC_ERANGE: return "result out of range";
  default: return "unknown status";
  }
}
