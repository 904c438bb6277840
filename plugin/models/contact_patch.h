/* The contact patch (dc/contract.h: semi-axes, major-axis direction,
   elastic normal force, the normal force that bounds friction, formed
   flag), passed from a normal model to the other sub-models of the same
   contact through LIGGGHTS' contact history: the normal model stores it in
   history values found by the name "dc_patch"; a reader asks for it by
   registering the name "dc_patch_reader" in its constructor. Under a stock
   normal model (no "dc_patch") a reader gets the circular patch
   a = b = (R delta)^1/2. Data plumbing only. */
#ifndef DC_PLUGIN_CONTACT_PATCH_H
#define DC_PLUGIN_CONTACT_PATCH_H

#include <cstdio>
#include <cstring>
#include "atom.h"
#include "comm.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "contact_frame.h"
#include "dc/contract.h"

namespace LIGGGHTS {
namespace ContactModels {

/* Normal models: stores the patch when a reader asked for it or the deck
   said `contactPatch on` (so that compute pair/gran/local and
   wall/gran/local with `history` show it). */
class ContactPatchWriter {
public:
  ContactPatchWriter() : offset_(-1) {}

  /* Call from postSettings (after every sub-model's constructor). */
  void setup(LAMMPS_NS::LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb, bool requested,
             const char *model)
  {
    if (!requested && cmb->get_history_offset("dc_patch_reader") < 0) return;
    for (int k = 0; k < DC_PATCH_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_patch_history[k].name, dc_patch_history[k].flips ? "1" : "0");
      if (k == 0) offset_ = off;
    }
    cmb->add_history_offset("dc_patch", offset_);
    if (lmp->comm->me != 0) return;
    FILE *out[2] = {lmp->screen, lmp->logfile};
    for (int k = 0; k < 2; k++)
      if (out[k])
        fprintf(out[k], "Normal model %s: contact patch in history values %d to %d (%s)\n", model, offset_,
                offset_ + DC_PATCH_NFIELDS - 1, cmb->is_wall() ? "wall" : "pair");
  }

  bool active() const { return offset_ >= 0; }

  void write(SurfacesCloseData &d, const dc_patch &p) const
  {
    memcpy(&d.contact_history[offset_], &p, sizeof p);
  }

  /* No contact: every field 0. */
  void clear(SurfacesCloseData &d) const
  {
    memset(&d.contact_history[offset_], 0, sizeof(dc_patch));
  }

private:
  int offset_;
};

/* Tangential, rolling and twisting models: the patch of the contact. */
class ContactPatchReader {
public:
  ContactPatchReader() : offset_(-1), superquadric_atoms_(false) {}

  /* Call from the sub-model's constructor. */
  void request(ContactModelBase *cmb) { cmb->add_history_offset("dc_patch_reader", 0, true); }

  /* Call from the sub-model's postSettings. */
  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb)
  {
    offset_ = cmb->get_history_offset("dc_patch");
    superquadric_atoms_ = lmp->atom->superquadric_flag;
  }

  /* Whether the normal model keeps this contact formed (false under a
     stock normal model, whose contacts end when the surfaces part). */
  bool formed(const SurfacesCloseData &d) const
  {
    return offset_ >= 0 && d.contact_history[offset_ + DC_PATCH_NFIELDS - 1] != 0.0;
  }

  /* The patch of a touching contact; under a stock normal model the circle
     of radius (R delta)^1/2 with the elastic force kn delta. */
  void read(const SurfacesIntersectData &sidata, dc_patch &p) const
  {
    if (offset_ >= 0) {
      memcpy(&p, &sidata.contact_history[offset_], sizeof p);
      return;
    }
    dc_patch_circular(stockEffectiveRadius(sidata, superquadric_atoms_), sidata.deltan, sidata.kn * sidata.deltan, &p);
  }

private:
  int offset_;
  bool superquadric_atoms_;
};

}
}
#endif
