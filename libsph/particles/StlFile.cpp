// Reading an STL file through VTK: see StlFile.hpp.
#include "particles/StlFile.hpp"
#include "particles/VtkMessages.hpp"
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vtkCellArray.h>
#include <vtkExecutive.h>
#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>

namespace shizuku {

namespace {

// VTK's first message, its first line, at most 200 characters (what follows is the
// pipeline's failure and a dump of its state; a parse error quotes the file).
std::string vtkSays(const std::string& text) {
  if (text.empty()) return "";
  std::string line = text.substr(0, std::min(text.find('\n'), text.find("; ")));  // VtkMessages joins with "; "
  if (line.size() > 200) line = line.substr(0, 200) + "...";
  return " (VTK: " + line + ")";
}

// The edges used by one triangle or by more than two.
long countOpenEdges(vtkPolyData* surface) {
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(surface);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->ColoringOff();
  edges->Update();
  return long(edges->GetOutput()->GetNumberOfCells());
}

}  // namespace

std::string readStl(const std::string& path, StlMesh& mesh) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return fs::exists(path, ec) ? "is not a file" : "does not exist";
  if (!std::ifstream(path)) return "cannot be opened (permissions?)";
  if (fs::file_size(path, ec) == 0) return "is empty";
  vtkNew<vtkSTLReader> reader;
  vtkNew<VtkMessages> messages;
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->AddObserver(vtkCommand::WarningEvent, messages);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* surface = reader->GetOutput();
  const std::string vtk = vtkSays(messages->text);
  if (!surface || !surface->GetPolys() || surface->GetPolys()->GetNumberOfCells() == 0)
    return "holds no triangle: not an STL file, or an empty solid" + vtk;
  if (!messages->text.empty()) return "could not be read" + vtk;
  mesh.points.resize(std::size_t(surface->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i) {
    double x[3];
    surface->GetPoint(i, x);
    mesh.points[std::size_t(i)] = Vec<3>(x[0], x[1], x[2]);
  }
  mesh.triangles.clear();
  vtkCellArray* polys = surface->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    if (n == 3) mesh.triangles.push_back({int(ids[0]), int(ids[1]), int(ids[2])});
  if (mesh.triangles.empty()) return "holds no triangle";
  mesh.openEdges = countOpenEdges(surface);
  return "";
}

}  // namespace shizuku
