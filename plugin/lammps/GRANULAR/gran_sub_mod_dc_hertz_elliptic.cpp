/* dc/hertz_elliptic (gran_sub_mod_dc_hertz_elliptic.h). */
#include "gran_sub_mod_dc_hertz_elliptic.h"

#include "dc/hertz_elliptic.h"

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModNormalDcHertzElliptic::GranSubModNormalDcHertzElliptic(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDcNormal(gm, lmp)
{
  num_coeffs = 3;
}

void GranSubModNormalDcHertzElliptic::coeffs_to_local()
{
  check_coeff("E", coeffs[0], 0.0, 1, HUGE_VAL, 1, "(0, inf)");
  check_coeff("damp", coeffs[1], 0.0, 0, HUGE_VAL, 1, "[0, inf)");
  check_coeff("nu", coeffs[2], -1.0, 1, 0.5, 0, "(-1, 0.5]");
  damp = coeffs[1];
  material_from(coeffs[0], coeffs[2]);
}

void GranSubModNormalDcHertzElliptic::mix_coeffs(double *icoeffs, double *jcoeffs)
{
  mix_material(icoeffs[0], icoeffs[2], jcoeffs[0], jcoeffs[2]);
  coeffs[0] = icoeffs[0] == jcoeffs[0] ? icoeffs[0] : mix_geom(icoeffs[0], jcoeffs[0]);
  coeffs[1] = mix_geom(icoeffs[1], jcoeffs[1]);
  coeffs[2] = mix_geom(icoeffs[2], jcoeffs[2]);
  coeffs_to_local();
}

/* Spheres: the circle of radius (R delta)^1/2, R the effective radius;
   the arithmetic of the LIGGGHTS model's sphere path. */
void GranSubModNormalDcHertzElliptic::evaluate()
{
  const double R = gm->Reff, delta = gm->delta;
  double kn;
  radius_ = dc_hertz_stiffness(Estar_, R, delta, &kn, &S_);
  F_ = kn * delta;
  if (patch_wanted_ && !dc_hertz_patch_circle(R, delta, F_, &patch_)) {
    dc_hertz_geom g;
    dc_contact c;
    dc_hertz_geometry_circle(R, &g);
    dc_hertz_normal(&g, Estar_, delta, &c);
    dc_patch_from_contact(&c, nullptr, &patch_);
  }
}
