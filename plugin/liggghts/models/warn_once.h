/* Warnings given once per process for the pair style and every wall
   together (each sub-model instance would otherwise warn again). Data
   plumbing only. */
#ifndef DC_PLUGIN_WARN_ONCE_H
#define DC_PLUGIN_WARN_ONCE_H

namespace LIGGGHTS {
namespace ContactModels {

enum DcWarning { DC_WARN_HERTZ_RANGE, DC_WARN_GWA_RATIO, DC_WARN_GWA_MESH, DC_WARN_COUNT };

/* false the first time for a kind (the caller then warns), true after */
inline bool warnedBefore(DcWarning kind)
{
  static bool given[DC_WARN_COUNT];
  const bool was = given[kind];
  given[kind] = true;
  return was;
}

}
}
#endif
