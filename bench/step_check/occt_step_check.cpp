// occt_step_check FILE.step [EXPECTED_CURVES]: reads a STEP file with OpenCASCADE's
// STEPControl_Reader (the reader CAD systems built on OCCT use) and reports what it made of it:
// load and transfer status, fail and warning counts of both check lists, roots, edges with a 3D
// curve and their total length. Exit status 1 when OCCT fails to load or transfer, reports a
// fail, or finds fewer edges than EXPECTED_CURVES. Built with -DSSIMARCH_BENCH_PEERS=ON
// (docs/cad.md, "OpenCASCADE reads the output").
#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>
#include <cstdio>
#include <cstdlib>

namespace {

// Fails and warnings of a check list (Interface_CheckIterator walks the entities with checks);
// each fail's message goes to stderr.
void count_checks(const Interface_CheckIterator& list, int* fails, int* warnings) {
  for (list.Start(); list.More(); list.Next()) {
    const Handle(Interface_Check)& check = list.Value();
    *fails += check->NbFails();
    *warnings += check->NbWarnings();
    for (int i = 1; i <= check->NbFails(); ++i)
      std::fprintf(stderr, "OCCT fail (entity %d): %s\n", list.Number(), check->CFail(i, Standard_False));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: occt_step_check FILE.step [EXPECTED_CURVES]\n");
    return 2;
  }
  const int expected = argc > 2 ? std::atoi(argv[2]) : 0;
  STEPControl_Reader reader;
  const IFSelect_ReturnStatus load = reader.ReadFile(argv[1]);
  int fails = 0, warnings = 0;
  count_checks(reader.WS()->ModelCheckList(), &fails, &warnings);
  const int roots = load == IFSelect_RetDone ? reader.NbRootsForTransfer() : 0;
  const int transferred = load == IFSelect_RetDone ? reader.TransferRoots() : 0;
  count_checks(reader.WS()->TransferReader()->TransientProcess()->CheckList(Standard_False), &fails, &warnings);
  int edges = 0;
  double length = 0;
  if (transferred > 0) {
    for (TopExp_Explorer e(reader.OneShape(), TopAbs_EDGE); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
      Standard_Real first, last;
      if (BRep_Tool::Curve(edge, first, last).IsNull()) continue;
      ++edges;
      length += GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(edge));
    }
  }
  std::printf("{\"file\": \"%s\", \"load\": %s, \"roots\": %d, \"transferred\": %d, \"fails\": %d, \"warnings\": %d, "
              "\"edges\": %d, \"length\": %.12g}\n",
              argv[1], load == IFSelect_RetDone ? "true" : "false", roots, transferred, fails, warnings, edges, length);
  return load == IFSelect_RetDone && transferred > 0 && fails == 0 && edges >= expected ? 0 : 1;
}
