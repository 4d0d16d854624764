// OpenCASCADE's section of a STEP model by planes, for the comparison with `ssimarch section` in
// docs/cad.md ("Sections against OpenCASCADE"; issue 28 item 5):
//
//   occt_section MODEL.step X,Y,Z,NX,NY,NZ [X,Y,Z,NX,NY,NZ ...] [--unit MM|INCH|M] [--per-face] [--verbose: every
//   edge's ends and length]
//
// The model is read by STEPControl_Reader in the file's own length unit (xstep.cascade.unit set
// to it, so coordinates match ssimarch's, which keeps the file's unit), and each plane cuts the
// whole shape by BRepAlgoAPI_Section (no approximation of the curves); with --per-face each face
// is cut alone and the results summed, as `ssimarch section` reports one curve per face (the
// whole-shape section merges the coincident curves of faces that touch, e.g. a bolt in its hole).
// Prints one line per plane: the edges, their total length (GCPnts_AbscissaPoint on each edge),
// the section's wall time.
#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <gp_Pln.hxx>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool plane_of(const std::string& text, gp_Pln* out) {
  std::vector<double> x;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) x.push_back(std::atof(item.c_str()));
  if (x.size() != 6) return false;
  *out = gp_Pln(gp_Pnt(x[0], x[1], x[2]), gp_Dir(x[3], x[4], x[5]));
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: occt_section MODEL.step X,Y,Z,NX,NY,NZ [...] [--unit MM|INCH|M]\n");
    return 2;
  }
  std::string unit = "MM";
  bool per_face = false, verbose = false;
  std::vector<std::string> planes;
  for (int i = 2; i < argc; ++i) {
    if (std::string(argv[i]) == "--unit" && i + 1 < argc)
      unit = argv[++i];
    else if (std::string(argv[i]) == "--per-face")
      per_face = true;
    else if (std::string(argv[i]) == "--verbose")
      verbose = true;
    else
      planes.push_back(argv[i]);
  }
  STEPControl_Reader reader;  // first: it registers the static parameters the next line sets
  Interface_Static::SetCVal("xstep.cascade.unit", unit.c_str());
  if (reader.ReadFile(argv[1]) != IFSelect_RetDone) {
    std::fprintf(stderr, "occt_section: cannot read %s\n", argv[1]);
    return 2;
  }
  reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  for (const std::string& text : planes) {
    gp_Pln pln;
    if (!plane_of(text, &pln)) {
      std::fprintf(stderr, "occt_section: bad plane %s\n", text.c_str());
      return 2;
    }
    std::vector<TopoDS_Shape> parts;
    if (per_face)
      for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) parts.push_back(f.Current());
    else
      parts.push_back(shape);
    int edges = 0;
    double length = 0, ms = 0;
    bool done = true;
    for (const TopoDS_Shape& part : parts) {
      const auto t0 = std::chrono::steady_clock::now();
      BRepAlgoAPI_Section section(part, pln, Standard_False);
      section.Approximation(Standard_False);
      section.Build();
      ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      done = done && section.IsDone();
      double here = 0;
      for (TopExp_Explorer e(section.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
        BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
        const double l = GCPnts_AbscissaPoint::Length(c);
        here += l;
        ++edges;
        if (verbose) {
          const gp_Pnt a = c.Value(c.FirstParameter()), b = c.Value(c.LastParameter());
          std::printf("  edge (%.6f, %.6f, %.6f)-(%.6f, %.6f, %.6f): length %.10f\n", a.X(), a.Y(), a.Z(), b.X(), b.Y(),
                      b.Z(), l);
        }
      }
      length += here;
    }
    std::printf("%s plane %s%s: %d edges, length %.10f, %.1f ms%s\n", argv[1], text.c_str(),
                per_face ? " per face" : "", edges, length, ms, done ? "" : " (not done)");
  }
  return 0;
}
