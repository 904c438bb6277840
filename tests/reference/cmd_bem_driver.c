/* Drives dc_cmd_step (dc/cmd_tangential.h) along a prescribed history for
   the comparison with the boundary-element reference of gen_cmd_bem.py.
   Not part of the CMake build. Build against the library:
     cmake -S . -B /tmp/build_bem -DCMAKE_BUILD_TYPE=Release
     cmake --build /tmp/build_bem -j2 --target demcontact
     cc -O2 -std=c11 -Ic_core/include tests/reference/cmd_bem_driver.c \
        /tmp/build_bem/c_core/libdemcontact.a -lgsl -lgslcblas -lm -o /tmp/cmd_bem_driver
   Usage: cmd_bem_driver b nu < increments
   Fixed contact (a = 1 >= b, major axis along x, normal along z, F_bound =
   1, mu = 1, compliance sums s0 = 1, s1 = nu: one elastic body of G = 1 on a
   rigid one), twisting on. Each input line "dux duy dphi" is one step (the
   displacement increment in the plane, along the major and minor axes, and
   the twist increment); each output line is
     Fx Fy stick Mt stick_twist
   (force components along the axes, stuck fraction of the radius for the
   force, twisting moment, stuck fraction for the twist = kr / k_twist). */
#include "dc/cmd_tangential.h"
#include "dc/status.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: %s b nu < increments\n", argv[0]);
    return 2;
  }
  const double b = atof(argv[1]), nu = atof(argv[2]);
  const dc_cmd_params p = {1.0, 0.0, 0, 1};
  const dc_mindlin_pair m = {1.0, nu};
  dc_patch pa;
  memset(&pa, 0, sizeof pa);
  pa.a = 1.0;
  pa.b = b;
  if (b < 1.0) pa.axis[0] = 1.0;
  pa.F_elastic = 1.0;
  pa.F_bound = 1.0;
  pa.formed = 1.0;
  double ktw;
  if (dc_cmd_twist_stiffness(&m, 1.0, b, &ktw) != DC_OK) {
    fprintf(stderr, "cmd_bem_driver: bad b or nu\n");
    return 1;
  }
  const double n[3] = {0.0, 0.0, 1.0};
  dc_cmd_state h;
  memset(&h, 0, sizeof h);
  double dux, duy, dphi;
  while (scanf("%lf %lf %lf", &dux, &duy, &dphi) == 3) {
    const double du[3] = {dux, duy, 0.0};
    dc_cmd_out o;
    const int rc = dc_cmd_step(&p, &m, &pa, n, du, dphi, 1e-6, &h, &o);
    if (rc != DC_OK) {
      fprintf(stderr, "cmd_bem_driver: dc_cmd_step returned %d\n", rc);
      return 1;
    }
    printf("%.17g %.17g %.17g %.17g %.17g\n", o.Ft[0], o.Ft[1], o.stick, o.Mt, o.kr / ktw);
  }
  return 0;
}
