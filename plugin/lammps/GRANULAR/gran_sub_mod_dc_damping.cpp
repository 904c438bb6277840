/* The project's damping laws as LAMMPS damping sub-models
   (gran_sub_mod_dc_damping.h). */
#include "gran_sub_mod_dc_damping.h"

#include "dc/damping.h"
#include "dc_sub_mod.h"

using namespace LAMMPS_NS;
using namespace Granular_NS;

GranSubModDampingDc::GranSubModDampingDc(GranularModel *gm, LAMMPS *lmp, int law) :
    GranSubModDamping(gm, lmp), law(law), coef(0.0), normal(nullptr)
{
}

GranSubModDampingDcRestitution::GranSubModDampingDcRestitution(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDampingDc(gm, lmp, DC_DAMPING_RESTITUTION)
{
}
GranSubModDampingDcViscoelastic::GranSubModDampingDcViscoelastic(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDampingDc(gm, lmp, DC_DAMPING_VISCOELASTIC)
{
}
GranSubModDampingDcKuwabaraKono::GranSubModDampingDcKuwabaraKono(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDampingDc(gm, lmp, DC_DAMPING_KUWABARA_KONO)
{
}
GranSubModDampingDcTsuji::GranSubModDampingDcTsuji(GranularModel *gm, LAMMPS *lmp) :
    GranSubModDampingDc(gm, lmp, DC_DAMPING_TSUJI)
{
}

void GranSubModDampingDc::init()
{
  GranSubModDamping::init();
  normal = dc_normal(gm);
  if (!normal)
    error->all(FLERR, "Damping {} acts on the tangent stiffness of a dc/ normal model, not on {}", name,
               gm->normal_model->name);
  // the coefficient of the law from the normal model's damp
  switch (law) {
    case DC_DAMPING_RESTITUTION:
    case DC_DAMPING_TSUJI:
      dc_check_coeff(error, name, "damp (coefficient of restitution)", damp, 0.0, 1, 1.0, 0, "(0, 1]");
      if (law == DC_DAMPING_RESTITUTION)
        dc_damping_beta(damp, &coef);
      else
        dc_damping_tsuji_alpha(damp, &coef);
      break;
    default:
      dc_check_coeff(error, name, "damp", damp, 0.0, 0, HUGE_VAL, 1, "[0, inf)");
      coef = damp;
  }
}

/* As the LIGGGHTS models' applyForce: the viscoelastic law acts on a
   negative stiffness too, the others on max(S, 0) and max(delta, 0). */
double GranSubModDampingDc::calculate_forces()
{
  const double S = normal->stiffness();
  if (law == DC_DAMPING_VISCOELASTIC)
    damp_prefactor = dc_damping_viscoelastic(coef, S);
  else
    damp_prefactor = dc_damping_gamma(law, coef, S > 0.0 ? S : 0.0, gm->delta > 0.0 ? gm->delta : 0.0, gm->meff);
  return -damp_prefactor * gm->vnnr;
}

double GranSubModDampingDc::gamma_of(double S) const
{
  return dc_damping_gamma(law, coef, S, gm->delta > 0.0 ? gm->delta : 0.0, gm->meff);
}
