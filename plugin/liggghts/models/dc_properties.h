/* Deck properties that more than one project model reads. Each has one
   creator here, so that LIGGGHTS' property registry sees one
   implementation whichever models a deck combines (two creators for one
   name make it print "property with the same name, but different
   implementation registered"). */
#ifndef DC_PLUGIN_PROPERTIES_H
#define DC_PLUGIN_PROPERTIES_H

#include "contact_models.h"
#include "global_properties.h"
#include "property_registry.h"

namespace LIGGGHTS {
namespace ContactModels {

/* workOfAdhesion peratomtypepair [J/m^2] >= 0 */
inline MatrixProperty *dcCreateWorkOfAdhesion(PropertyRegistry &registry, const char *caller, bool sanity_checks)
{
  return MODEL_PARAMS::createPerTypePairProperty(registry, "workOfAdhesion", caller, sanity_checks, 0.0);
}

/* equilibriumSeparation peratomtypepair [m] > 0: z0 of the surfaces'
   Lennard-Jones potential (adhesionLaw maugis and tabor) */
inline MatrixProperty *dcCreateEquilibriumSeparation(PropertyRegistry &registry, const char *caller, bool sanity_checks)
{
  return MODEL_PARAMS::createPerTypePairProperty(registry, "equilibriumSeparation", caller, sanity_checks, 0.0);
}

/* surfaceRoughness peratomtype [m] >= 0, registered as surfaceRoughnessType */
inline VectorProperty *dcCreateRoughnessType(PropertyRegistry &registry, const char *caller, bool sanity_checks)
{
  return MODEL_PARAMS::createPerTypeProperty(registry, "surfaceRoughness", caller, sanity_checks, 0.0);
}

/* asperityCount peratomtypepair > 0 */
inline MatrixProperty *dcCreateAsperityCount(PropertyRegistry &registry, const char *caller, bool sanity_checks)
{
  return MODEL_PARAMS::createPerTypePairProperty(registry, "asperityCount", caller, sanity_checks, 1e-300);
}

}
}
#endif
