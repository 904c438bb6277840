/* The law contract: the shape every c_core contact law has, and the contact
   patch a normal law hands to the other sub-models of a contact.

   A law family (one header in dc/) provides:
   1. Parameters per material (type) pair, checked once at set-up by
      dc_<law>_check(...): DC_OK, or DC_EDOM with a dc_param_error naming
      the parameter, its value and its valid range. A wrapper reports it
      with the type pair, before the first contact (dc_param_error_format).
   2. An optional per-contact geometry (relative principal radii and what
      depends only on them: dc_hertz_geom, dc_jkr_geom), computed once per
      contact and step where the shape changes, never for spheres.
   3. A plain-data per-contact history of doubles (or none) with a table of
      its fields, dc_<law>_history[] (name, and whether the value changes
      sign when i and j swap), so that a wrapper registers it in a loop.
      Start value 0 for every field.
   4. One output, dc_contact: elastic force, tangent stiffness dF/d delta,
      area, semi-axes, the normal force that bounds friction and whether the
      contact is formed; the major-axis direction comes from the geometry
      (dc_form_major_axis) where the contact is elliptic.
   Status codes (dc/status.h): an error leaves every output untouched, DC_OK
   never comes with a NaN or Inf, non-finite inputs are DC_EDOM. */
#ifndef DC_CONTRACT_H
#define DC_CONTRACT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One field of a law's per-contact history. */
typedef struct {
  const char *name;  /* unique across the project's laws, e.g. "jkr_contact" */
  int flips;         /* 1: the value changes sign when i and j swap */
} dc_history_field;

/* A parameter outside its domain: what a wrapper needs for its message. */
typedef struct {
  const char *name;  /* the deck's property name, e.g. "workOfAdhesion" */
  double value;
  const char *range; /* the valid range as text, e.g. "[0, inf)" */
} dc_param_error;

/* Checks lo <= value <= hi (lo_open / hi_open: strict) and finiteness; on
   failure fills err (name, value, range) and returns DC_EDOM. */
int dc_param_check(const char *name, double value, double lo, int lo_open,
                   double hi, int hi_open, const char *range, dc_param_error *err);

/* "<name> = <value> for types i and j is outside <range>" into buf. */
void dc_param_error_format(const dc_param_error *err, int itype, int jtype, char *buf, size_t n);

/* What a normal law knows about one contact at one step. */
typedef struct {
  double F;        /* elastic normal force [N], > 0 repulsive */
  double kn;       /* tangent stiffness dF/d delta [N/m] */
  double area;     /* contact area [m^2] */
  double a, b;     /* semi-axes of the contact ellipse [m], a >= b >= 0 */
  double F_bound;  /* normal force that bounds friction, |F_t| <= mu F_bound [N]
                      (>= 0; F for non-adhesive laws, F + 2 F_pull for JKR) */
  int formed;      /* 1: the contact acts (an adhesive neck in tension, a
                      rough contact before touch); 0: no contact */
} dc_contact;

/* The contact patch as other sub-models see it: a flat record of doubles,
   stored per contact (LIGGGHTS: contact history values, dc_patch_history). */
typedef struct {
  double a, b;       /* semi-axes [m], a >= b */
  double axis[3];    /* unit major-axis direction in the contact plane;
                        zero for a circular patch (a == b) */
  double F_elastic;  /* elastic normal force [N] */
  double F_bound;    /* normal force that bounds friction [N] */
  double formed;     /* 1 formed, 0 not */
} dc_patch;

enum { DC_PATCH_NFIELDS = 8 };
extern const dc_history_field dc_patch_history[DC_PATCH_NFIELDS];

/* The patch of a contact with major-axis direction axis (NULL or zero for
   a circle). */
static inline void dc_patch_from_contact(const dc_contact *c, const double *axis, dc_patch *p)
{
  p->a = c->a;
  p->b = c->b;
  p->axis[0] = axis ? axis[0] : 0.0;
  p->axis[1] = axis ? axis[1] : 0.0;
  p->axis[2] = axis ? axis[2] : 0.0;
  p->F_elastic = c->F;
  p->F_bound = c->F_bound;
  p->formed = c->formed ? 1.0 : 0.0;
}

/* The circular patch of a contact whose law publishes none (a stock normal
   law): a = b = (R delta)^1/2 for delta > 0, elastic force F. */
void dc_patch_circular(double R, double delta, double F, dc_patch *p);

#ifdef __cplusplus
}
#endif
#endif
