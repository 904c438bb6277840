/* The contact patch (dc/contract.h: semi-axes, major-axis direction,
   elastic normal force, the normal force that bounds friction, formed
   flag), passed from a normal model to the other sub-models of the same
   contact in memory, within the same evaluation (contact_slot.h): the
   normal model writes it in every call (surfacesIntersect and
   surfacesClose) before the others run; a reader asks for it by
   registering the name "dc_patch_reader" in its constructor. With
   `contactPatch on` the normal model also stores it in history values
   (for compute pair/gran/local and wall/gran/local with `history`).
   Under a stock normal model (nothing offered) a reader gets the circular
   patch a = b = (R delta)^1/2. Data plumbing only. */
#ifndef DC_PLUGIN_CONTACT_PATCH_H
#define DC_PLUGIN_CONTACT_PATCH_H

#include <cstdio>
#include <cstring>
#include "atom.h"
#include "comm.h"
#include "contact_interface.h"
#include "contact_models.h"
#include "contact_frame.h"
#include "contact_slot.h"
#include "dc/contract.h"

namespace LIGGGHTS {
namespace ContactModels {

/* Normal models: keeps the patch when a reader asked for it, stores it
   when the deck said `contactPatch on`. */
class ContactPatchWriter {
public:
  ContactPatchWriter() : offset_(-1), cmb_(0), read_(false), active_(false) { memset(&current_, 0, sizeof current_); }
  ~ContactPatchWriter()
  {
    if (read_) ContactSlots::withdraw(cmb_, "dc_patch");
  }

  /* Call from postSettings (after every sub-model's constructor). */
  void setup(LAMMPS_NS::LAMMPS *lmp, IContactHistorySetup *hsetup, ContactModelBase *cmb, bool stored,
             const char *model)
  {
    cmb_ = cmb;
    read_ = cmb->get_history_offset("dc_patch_reader") >= 0;
    active_ = read_ || stored;
    if (read_) ContactSlots::offer(cmb, "dc_patch", &current_);
    if (!stored) return;
    for (int k = 0; k < DC_PATCH_NFIELDS; k++) {
      const int off = hsetup->add_history_value(dc_patch_history[k].name, dc_patch_history[k].flips ? "1" : "0");
      if (k == 0) offset_ = off;
    }
    if (lmp->comm->me != 0) return;
    FILE *out[2] = {lmp->screen, lmp->logfile};
    for (int k = 0; k < 2; k++)
      if (out[k])
        fprintf(out[k], "Normal model %s: contact patch in history values %d to %d (%s)\n", model, offset_,
                offset_ + DC_PATCH_NFIELDS - 1, cmb->is_wall() ? "wall" : "pair");
  }

  /* Whether anything reads the patch (a sub-model, or the history). */
  bool active() const { return active_; }

  /* The patch of this evaluation, to be filled by the normal model and
     handed over by commit(). */
  dc_patch &next() { return current_; }

  void commit(SurfacesCloseData &d) const
  {
    if (offset_ >= 0) memcpy(&d.contact_history[offset_], &current_, sizeof current_);
  }

  /* No contact: every field 0. */
  void clear(SurfacesCloseData &d)
  {
    memset(&current_, 0, sizeof current_);
    commit(d);
  }

private:
  dc_patch current_;
  int offset_;                /* history values, with contactPatch on; else -1 */
  const ContactModelBase *cmb_;
  bool read_;                 /* a sub-model reads current_ */
  bool active_;               /* read_ or stored */
};

/* The summits' patch of a rough contact (gw_rough: dc_rough_tangential_axes
   on the smooth patch's forces and axis), for a tangential model with
   tangentialRoughness on. The normal model offers it as "dc_rough_patch"
   in its postSettings and fills it in every call once a reader, in its own
   (later) postSettings, has set wanted. Data plumbing only. */
struct RoughPatchSlot {
  dc_patch patch;
  bool wanted;
};

/* Tangential, rolling and twisting models: the patch of the contact. */
class ContactPatchReader {
public:
  ContactPatchReader() : written_(0), superquadric_atoms_(false) {}

  /* Call from the sub-model's constructor. */
  void request(ContactModelBase *cmb) { cmb->add_history_offset("dc_patch_reader", 0, true); }

  /* Call from the sub-model's postSettings. */
  void setup(LAMMPS_NS::LAMMPS *lmp, ContactModelBase *cmb)
  {
    written_ = ContactSlots::find<const dc_patch>(cmb, "dc_patch");
    superquadric_atoms_ = lmp->atom->superquadric_flag;
  }

  /* Whether the normal model publishes the patch. */
  bool published() const { return written_ != 0; }

  /* The normal model's patch of this evaluation (when published()). */
  const dc_patch &publishedPatch() const { return *written_; }

  /* Whether the normal model keeps this contact formed (false under a
     stock normal model, whose contacts end when the surfaces part). */
  bool formed() const { return written_ && written_->formed != 0.0; }

  /* The patch of a touching contact: the normal model's, read in place
     (no copy: its fields were just stored one by one, and a copy's wider
     loads would wait for them); under a stock normal model the circle of
     radius (R delta)^1/2 with the elastic force kn delta, made in stock. */
  __attribute__((always_inline)) inline const dc_patch &read(const SurfacesIntersectData &sidata, dc_patch &stock) const
  {
    if (written_) return *written_;
    dc_patch_circular(stockEffectiveRadius(sidata, superquadric_atoms_), sidata.deltan, sidata.kn * sidata.deltan, &stock);
    return stock;
  }

private:
  const dc_patch *written_;   /* the normal model's patch of this evaluation, or NULL */
  bool superquadric_atoms_;
};

}
}
#endif
