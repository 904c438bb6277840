/* The law contract's shared pieces: parameter checks, the patch layout. */
#include "dc/contract.h"
#include "dc/status.h"
#include <float.h>
#include <math.h>
#include <stdio.h>

const dc_history_field dc_patch_history[DC_PATCH_NFIELDS] = {
  {"patch_a", 0}, {"patch_b", 0},
  /* an axis and its opposite are the same axis: no flip needed */
  {"patch_axis_x", 0}, {"patch_axis_y", 0}, {"patch_axis_z", 0},
  {"patch_F_elastic", 0}, {"patch_F_bound", 0}, {"patch_formed", 0},
};

int dc_param_check(const char *name, double value, double lo, int lo_open,
                   double hi, int hi_open, const char *range, dc_param_error *err)
{
  const int ok = isfinite(value) && (lo_open ? value > lo : value >= lo) &&
                 (hi_open ? value < hi : value <= hi);
  if (ok) return DC_OK;
  err->name = name;
  err->value = value;
  err->range = range;
  return DC_EDOM;
}

void dc_param_error_format(const dc_param_error *err, int itype, int jtype, char *buf, size_t n)
{
  snprintf(buf, n, "%s = %g for types %d and %d is outside %s", err->name, err->value, itype, jtype,
           err->range);
}

void dc_patch_circular(double R, double delta, double F, dc_patch *p)
{
  const double Rd = R * delta;
  double a = delta > 0.0 ? sqrt(Rd) : 0.0;
  if (delta > 0.0 && !(Rd >= DBL_MIN && Rd <= DBL_MAX)) a = sqrt(R) * sqrt(delta);   /* R delta out of range */
  p->a = p->b = a;
  p->axis[0] = p->axis[1] = p->axis[2] = 0.0;
  p->F_elastic = F;
  p->F_bound = F > 0.0 ? F : 0.0;
  p->formed = delta > 0.0 ? 1.0 : 0.0;
}
