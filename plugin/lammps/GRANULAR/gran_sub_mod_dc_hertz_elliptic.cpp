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
  material_coeffs();
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
  hertz_circle(gm->Reff, gm->delta);
}
