// particles.pvd (docs/design.md 1.3) opens the whole series with correct times:
// written out of order, the collection must list every complete time directory
// sorted by time; it is read back with VTK's own XML parser and each listed
// vtp through vtkXMLPolyDataReader, checking the point count, vertex cells,
// point-data fields, and that the field-data TimeValue equals the timestep.
#define BOOST_TEST_MODULE io_pvd
#include <boost/test/unit_test.hpp>
#include "io/TimeDirectory.hpp"
#include "io/TimeName.hpp"
#include "test_io_helpers.hpp"
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

using namespace shizuku;
using namespace shizuku::iotest;

BOOST_AUTO_TEST_CASE(seriesListsEveryTimeSorted) {
  ScratchDir c;
  const std::vector<double> times = {4.3, 0, 0.25, 1e-05, 1234.5, 0.1};  // written out of order
  std::map<double, ParticleSet<2>> sets;
  for (std::size_t k = 0; k < times.size(); ++k) {
    auto p = randomSet<2>(20 + k, k % 2 == 0, 100 + k);
    sets[times[k]] = p;
    writeTimeDirectory<2>(c.path, timeName(times[k]), p, TimeState{times[k], long(k), 1e-4, 1e-4, ""}, false);
  }

  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName((c.path + "/particles.pvd").c_str());
  BOOST_REQUIRE(parser->Parse() == 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  BOOST_REQUIRE(root);
  BOOST_TEST(std::string(root->GetName()) == "VTKFile");
  BOOST_TEST(std::string(root->GetAttribute("type")) == "Collection");
  vtkXMLDataElement* coll = root->FindNestedElementWithName("Collection");
  BOOST_REQUIRE(coll);
  BOOST_REQUIRE(coll->GetNumberOfNestedElements() == int(times.size()));

  std::vector<double> sorted = times;
  std::sort(sorted.begin(), sorted.end());
  for (int k = 0; k < coll->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* ds = coll->GetNestedElement(k);
    BOOST_TEST(std::string(ds->GetName()) == "DataSet");
    double t = 0;
    BOOST_REQUIRE(ds->GetScalarAttribute("timestep", t));
    BOOST_TEST(t == sorted[k]);
    const std::string file = ds->GetAttribute("file");
    BOOST_TEST(file == timeName(sorted[k]) + "/particles.vtp");

    vtkNew<vtkXMLPolyDataReader> r;
    r->SetFileName((c.path + "/" + file).c_str());  // relative to the pvd, as ParaView resolves it
    r->Update();
    vtkPolyData* pd = r->GetOutput();
    const ParticleSet<2>& p = sets[t];
    BOOST_REQUIRE(pd->GetNumberOfPoints() == vtkIdType(p.size()));
    BOOST_TEST(pd->GetVerts()->GetNumberOfCells() == vtkIdType(p.size()));
    BOOST_TEST(pd->GetFieldData()->GetArray("TimeValue")->GetTuple1(0) == t);
    vtkPointData* pt = pd->GetPointData();
    for (const char* name : {"U", "p", "rhoN", "type", "surface", "id"}) BOOST_TEST(pt->HasArray(name), name);
    BOOST_TEST(bool(pt->HasArray("shift")) == !p.shift.empty());
    BOOST_TEST(!pt->HasArray("normal"));
    BOOST_TEST(pt->GetArray("U")->GetNumberOfComponents() == 3);
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i) {
      double x[3];
      pd->GetPoint(i, x);
      BOOST_TEST(sameBits(x[0], p.position[i][0]));
      BOOST_TEST(sameBits(x[1], p.position[i][1]));
      BOOST_TEST(x[2] == 0.0);
      BOOST_TEST(sameBits(pt->GetArray("p")->GetTuple1(i), p.pressure[i]));
      BOOST_TEST(sameBits(pt->GetArray("U")->GetComponent(i, 1), p.velocity[i][1]));
      BOOST_TEST(pt->GetArray("U")->GetComponent(i, 2) == 0.0);
      BOOST_TEST(pt->GetArray("type")->GetTuple1(i) == double(p.type[i]));
    }
  }
}

BOOST_AUTO_TEST_CASE(emptyCaseHasEmptyCollection) {
  ScratchDir c;
  writePvd(c.path);
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName((c.path + "/particles.pvd").c_str());
  BOOST_REQUIRE(parser->Parse() == 1);
  BOOST_TEST(parser->GetRootElement()->FindNestedElementWithName("Collection")->GetNumberOfNestedElements() == 0);
  BOOST_TEST(listTimeDirectories(c.path + "/missing").empty());
}
