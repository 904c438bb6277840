/* dump custom/vtk without the VTK library: see dump_custom_vtk_plain.h. */
#include "dump_custom_vtk_plain.h"

#include <cstdio>
#include <cstring>
#include "domain.h"
#include "error.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {

/* dump columns grouped into one array (tools/dump2vtk.py's VECTORS) */
struct ColumnGroup {
  const char *cols[4];
  int n;
  const char *name;
};
const ColumnGroup GROUPS[] = {
    {{"vx", "vy", "vz"}, 3, "v"},          {{"fx", "fy", "fz"}, 3, "f"},
    {{"omegax", "omegay", "omegaz"}, 3, "omega"}, {{"tqx", "tqy", "tqz"}, 3, "tq"},
    {{"angmomx", "angmomy", "angmomz"}, 3, "angmom"}, {{"mux", "muy", "muz"}, 3, "mu"},
    {{"ix", "iy", "iz"}, 3, "image"},      {{"shapex", "shapey", "shapez"}, 3, "shape"},
    {{"blockiness1", "blockiness2"}, 2, "blockiness"}, {{"roundness1", "roundness2"}, 2, "blockiness"},
    {{"quat1", "quat2", "quat3", "quat4"}, 4, "quat"}};
const char *const INTEGERS[] = {"id", "type", "mol", "proc", "procp1", "ix", "iy", "iz"};
const char *const POSITIONS[][3] = {{"x", "y", "z"}, {"xu", "yu", "zu"}, {"xs", "ys", "zs"}, {"xsu", "ysu", "zsu"}};

bool integer(const std::string &c)
{
  for (const char *n : INTEGERS)
    if (c == n) return true;
  return false;
}

}

DumpCustomVTKPlain::DumpCustomVTKPlain(LAMMPS *lmp, int narg, char **arg) :
  DumpCustom(lmp, narg, arg), xml_(false), scaled_(false), expected_(0)
{
  if (!multifile)
    error->all(FLERR, "Dump custom/vtk writes one file per snapshot: put a '*' in the file name "
               "(e.g. post/dump_*.vtk), which becomes the step");
  const char *dot = strrchr(filename, '.');
  if (dot && strcmp(dot, ".vtp") == 0) xml_ = true;
  else if (!(dot && strcmp(dot, ".vtk") == 0))
    error->all(FLERR, "Dump custom/vtk: the file name must end in .vtk (legacy VTK) or .vtp (VTK XML PolyData)");
  buffer_allow = 0;   /* write_data receives the packed doubles */
  buffer_flag = 0;
  layout(narg, arg);
}

/* The points and the arrays from the dump's columns (arg[5...]). */
void DumpCustomVTKPlain::layout(int narg, char **arg)
{
  std::vector<std::string> cols;
  for (int i = 5; i < narg && (int)cols.size() < size_one; i++) cols.push_back(arg[i]);
  const int n = cols.size();
  std::vector<bool> used(n, false);
  auto find = [&](const char *name) {
    for (int k = 0; k < n; k++)
      if (!used[k] && cols[k] == name) return k;
    return -1;
  };
  int p = 0;
  for (; p < 4; p++) {
    const int a = find(POSITIONS[p][0]), b = find(POSITIONS[p][1]), c = find(POSITIONS[p][2]);
    if (a >= 0 && b >= 0 && c >= 0) {
      pos_[0] = a; pos_[1] = b; pos_[2] = c;
      used[a] = used[b] = used[c] = true;
      break;
    }
  }
  if (p == 4) error->all(FLERR, "Dump custom/vtk needs the positions: x y z (or xu yu zu, or xs ys zs)");
  scaled_ = p >= 2;
  if (scaled_ && domain->triclinic) error->all(FLERR, "Dump custom/vtk: scaled positions need an orthogonal box");
  for (int k = 0; k < n; k++) {
    if (used[k]) continue;
    bool grouped = false;
    for (const ColumnGroup &g : GROUPS) {
      if (cols[k] != g.cols[0]) continue;
      Field f;
      for (int c = 0; c < g.n; c++) {
        const int at = find(g.cols[c]);
        if (at < 0) break;
        f.cols.push_back(at);
      }
      if ((int)f.cols.size() != g.n) continue;
      for (int at : f.cols) used[at] = true;
      f.name = g.name;
      f.integer = integer(g.cols[0]);
      fields_.push_back(f);
      grouped = true;
      break;
    }
    if (grouped) continue;
    bool repeated = false;
    for (const Field &f : fields_) repeated |= f.name == cols[k];
    used[k] = true;
    if (repeated) continue;   /* a column listed twice: once */
    Field f;
    f.name = cols[k];
    f.cols.push_back(k);
    f.integer = integer(cols[k]);
    fields_.push_back(f);
  }
}

void DumpCustomVTKPlain::write_header(bigint n)
{
  expected_ = n;
  rows_.clear();
  if (n == 0) writeFile();
}

/* The rows of one process; the file is written once all have arrived. */
void DumpCustomVTKPlain::write_data(int n, double *mybuf)
{
  rows_.insert(rows_.end(), mybuf, mybuf + (size_t)n * size_one);
  if ((bigint)(rows_.size() / size_one) == expected_) writeFile();
}

void DumpCustomVTKPlain::writeFile()
{
  if (xml_) writeXml();
  else writeLegacy();
}

void DumpCustomVTKPlain::writeLegacy()
{
  const size_t n = rows_.size() / size_one;
  fprintf(fp, "# vtk DataFile Version 3.0\nLIGGGHTS dump custom/vtk, step " BIGINT_FORMAT "\nASCII\n"
          "DATASET POLYDATA\nPOINTS %zu double\n", update->ntimestep, n);
  for (size_t i = 0; i < n; i++) {
    const double *r = &rows_[i * size_one];
    for (int c = 0; c < 3; c++) {
      const double v = scaled_ ? domain->boxlo[c] + r[pos_[c]] * (domain->boxhi[c] - domain->boxlo[c]) : r[pos_[c]];
      fprintf(fp, c < 2 ? "%.17g " : "%.17g\n", v);
    }
  }
  fprintf(fp, "VERTICES %zu %zu\n", n, 2 * n);
  for (size_t i = 0; i < n; i++) fprintf(fp, "1 %zu\n", i);
  fprintf(fp, "POINT_DATA %zu\nFIELD FieldData %zu\n", n, fields_.size());
  for (const Field &f : fields_) {
    fprintf(fp, "%s %zu %zu %s\n", f.name.c_str(), f.cols.size(), n, f.integer ? "long" : "double");
    for (size_t i = 0; i < n; i++) {
      const double *r = &rows_[i * size_one];
      for (size_t c = 0; c < f.cols.size(); c++) {
        if (f.integer) fprintf(fp, "%lld", (long long)r[f.cols[c]]);
        else fprintf(fp, "%.17g", r[f.cols[c]]);
        fputc(c + 1 < f.cols.size() ? ' ' : '\n', fp);
      }
    }
  }
}

void DumpCustomVTKPlain::writeXml()
{
  const size_t n = rows_.size() / size_one;
  fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
          "header_type=\"UInt64\">\n  <PolyData>\n    <Piece NumberOfPoints=\"%zu\" NumberOfVerts=\"%zu\" "
          "NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n      <Points>\n        <DataArray "
          "type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">", n, n);
  for (size_t i = 0; i < n; i++) {
    const double *r = &rows_[i * size_one];
    for (int c = 0; c < 3; c++)
      fprintf(fp, " %.17g",
              scaled_ ? domain->boxlo[c] + r[pos_[c]] * (domain->boxhi[c] - domain->boxlo[c]) : r[pos_[c]]);
  }
  fprintf(fp, "</DataArray>\n      </Points>\n      <Verts>\n        <DataArray type=\"Int64\" Name=\"connectivity\" "
          "NumberOfComponents=\"1\" format=\"ascii\">");
  for (size_t i = 0; i < n; i++) fprintf(fp, " %zu", i);
  fprintf(fp, "</DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" NumberOfComponents=\"1\" "
          "format=\"ascii\">");
  for (size_t i = 0; i < n; i++) fprintf(fp, " %zu", i + 1);
  fprintf(fp, "</DataArray>\n      </Verts>\n      <PointData>\n");
  for (const Field &f : fields_) {
    fprintf(fp, "        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%zu\" format=\"ascii\">",
            f.integer ? "Int64" : "Float64", f.name.c_str(), f.cols.size());
    for (size_t i = 0; i < n; i++) {
      const double *r = &rows_[i * size_one];
      for (int c : f.cols) {
        if (f.integer) fprintf(fp, " %lld", (long long)r[c]);
        else fprintf(fp, " %.17g", r[c]);
      }
    }
    fprintf(fp, "</DataArray>\n");
  }
  fprintf(fp, "      </PointData>\n    </Piece>\n  </PolyData>\n</VTKFile>\n");
}
