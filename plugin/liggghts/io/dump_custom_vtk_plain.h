/* LIGGGHTS `dump custom/vtk` without the VTK library (Debian ships VTK 9,
   LIGGGHTS 3.8's own custom/vtk wants VTK 8 or older and is left out of
   this build). The deck line of LIGGGHTS' tutorials works unchanged:

     dump ID group custom/vtk N file_*.vtk field1 field2 ...   (legacy VTK, ASCII)
     dump ID group custom/vtk N file_*.vtp field1 field2 ...   (VTK XML PolyData, ASCII)

   with the fields of `dump custom`, one file per snapshot (the '*' in the
   name is replaced by the step, as dump custom does). Each particle is a
   point at x y z (or xu yu zu, or xs ys zs scaled by the box) with a vertex;
   the other columns are point data named as tools/dump2vtk.py names them:
   vx vy vz -> v, fx fy fz -> f, omegax.. -> omega, tqx.. -> tq, angmomx.. ->
   angmom, mux.. -> mu, ix iy iz -> image, shapex.. -> shape, blockiness1 2
   -> blockiness, quat1..4 -> quat, every other column a scalar of its own
   name (a repeated column once); id, type, mol, proc and image as integers.
   I/O only: no physics. */
#ifdef DUMP_CLASS

DumpStyle(custom/vtk,DumpCustomVTKPlain)

#else

#ifndef LMP_DUMP_CUSTOM_VTK_PLAIN_H
#define LMP_DUMP_CUSTOM_VTK_PLAIN_H

#include <string>
#include <vector>
#include "dump_custom.h"

namespace LAMMPS_NS {

class DumpCustomVTKPlain : public DumpCustom {
 public:
  DumpCustomVTKPlain(class LAMMPS *, int, char **);

 protected:
  void write_header(bigint);
  void write_data(int, double *);

 private:
  struct Field {
    std::string name;
    std::vector<int> cols;   /* the dump columns of its components */
    bool integer;
  };
  void layout(int narg, char **arg);
  void writeFile();
  void writeLegacy();
  void writeXml();

  bool xml_;                  /* .vtp: VTK XML; else legacy VTK */
  int pos_[3];                /* position columns */
  bool scaled_;               /* xs ys zs: scaled by the box */
  std::vector<Field> fields_;
  bigint expected_;           /* atoms in this snapshot */
  std::vector<double> rows_;  /* this snapshot's rows, size_one each */
};

}

#endif
#endif
