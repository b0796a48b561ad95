// particles.vtp writer and exact reader: see VtpFile.hpp (docs/design.md 1.3).
#include "io/VtpFile.hpp"
#include "io/FileOps.hpp"
#include "io/RestartChecks.hpp"
#include "io/TimeName.hpp"
#include "io/VtpLayout.hpp"
#include "particles/VtkMessages.hpp"
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt64Array.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

namespace shizuku {

namespace {

// The arrays of a write borrow the particle fields' storage where the layout is VTK's
// (one component; three-component vectors in 3D): the writer only reads them while the
// vtkPolyData lives, inside writeVtp, and a write then holds no copy of those fields.
// (The first n values of each field are written: a rank's own particles, not its ghosts.)
template <class A, class T>
vtkSmartPointer<vtkDataArray> borrowArray(const char* name, const T* v, std::size_t n, int components) {
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  // save = 1: VTK neither frees nor writes to the storage.
  a->SetArray(const_cast<T*>(v), vtkIdType(n) * components, 1);
  return a;
}

vtkSmartPointer<vtkDataArray> makeArray(const char* name, const std::vector<double>& v, std::size_t n) {
  return borrowArray<vtkDoubleArray>(name, v.data(), n, 1);
}
vtkSmartPointer<vtkDataArray> makeArray(const char* name, const std::vector<std::uint8_t>& v, std::size_t n) {
  return borrowArray<vtkUnsignedCharArray>(name, v.data(), n, 1);
}
vtkSmartPointer<vtkDataArray> makeArray(const char* name, const std::vector<std::int64_t>& v, std::size_t n) {
  return borrowArray<vtkTypeInt64Array>(name, reinterpret_cast<const vtkTypeInt64*>(v.data()), n, 1);
}

// Vectors as three components (2D: z = 0, a copy; 3D: the storage itself).
template <int D>
vtkSmartPointer<vtkDataArray> makeArray(const char* name, const std::vector<Vec<D>>& v, std::size_t count) {
  static_assert(sizeof(Vec<3>) == 3 * sizeof(double), "Vec<3> is three packed doubles");
  if constexpr (D == 3) return borrowArray<vtkDoubleArray>(name, v.empty() ? nullptr : v[0].data(), count, 3);
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(vtkIdType(count));
  double* x = a->GetPointer(0);
  const long n = long(count);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) x[3 * i + k] = k < D ? v[i][k] : 0.0;
  return a;
}

void addFieldValue(vtkFieldData* fd, const char* name, double value) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  fd->AddArray(a);
}

void addFieldValue(vtkFieldData* fd, const char* name, std::int64_t value) {
  vtkNew<vtkTypeInt64Array> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, value);
  fd->AddArray(a);
}

// --- reading -----------------------------------------------------------------

[[noreturn]] void corrupt(const std::string& path, const std::string& why) { corruptVtp(path, why); }

bool isInt64(const vtkAbstractArray* a) {
  int t = const_cast<vtkAbstractArray*>(a)->GetDataType();
  return (t == VTK_LONG || t == VTK_LONG_LONG || t == VTK_ID_TYPE || t == VTK_TYPE_INT64) &&
         const_cast<vtkAbstractArray*>(a)->GetDataTypeSize() == 8;
}

void checkShape(const std::string& path, const char* name, vtkDataArray* a, bool typeOk,
                const char* typeName, int components, vtkIdType n) {
  if (!typeOk) corrupt(path, std::string("array '") + name + "' is " + a->GetDataTypeAsString() +
                                 ", expected " + typeName);
  if (a->GetNumberOfComponents() != components)
    corrupt(path, std::string("array '") + name + "' has " + std::to_string(a->GetNumberOfComponents()) +
                      " components, expected " + std::to_string(components));
  if (a->GetNumberOfTuples() != n)
    corrupt(path, std::string("array '") + name + "' has " + std::to_string(a->GetNumberOfTuples()) +
                      " values for " + std::to_string(n) + " particles");
}

void readArray(const std::string& path, const char* name, vtkDataArray* a, vtkIdType n, std::vector<double>& v) {
  checkShape(path, name, a, a->GetDataType() == VTK_DOUBLE, "Float64", 1, n);
  v.resize(std::size_t(n));
  if (n) std::memcpy(v.data(), a->GetVoidPointer(0), std::size_t(n) * sizeof(double));
}

void readArray(const std::string& path, const char* name, vtkDataArray* a, vtkIdType n, std::vector<std::uint8_t>& v) {
  checkShape(path, name, a, a->GetDataType() == VTK_UNSIGNED_CHAR, "UInt8", 1, n);
  v.resize(std::size_t(n));
  if (n) std::memcpy(v.data(), a->GetVoidPointer(0), std::size_t(n));
}

void readArray(const std::string& path, const char* name, vtkDataArray* a, vtkIdType n, std::vector<std::int64_t>& v) {
  checkShape(path, name, a, isInt64(a), "Int64", 1, n);
  v.resize(std::size_t(n));
  if (n) std::memcpy(v.data(), a->GetVoidPointer(0), std::size_t(n) * sizeof(std::int64_t));
}

template <int D>
void readArray(const std::string& path, const char* name, vtkDataArray* a, vtkIdType n, std::vector<Vec<D>>& v) {
  checkShape(path, name, a, a->GetDataType() == VTK_DOUBLE, "Float64", 3, n);
  v.resize(std::size_t(n));
  const double* x = n ? static_cast<const double*>(a->GetVoidPointer(0)) : nullptr;
#pragma omp parallel for schedule(static)
  for (long i = 0; i < long(n); ++i)
    for (int k = 0; k < D; ++k) v[i][k] = x[3 * i + k];
}

// The single-value field data of one file.
class FieldValues {
 public:
  FieldValues(const std::string& path, vtkFieldData* fd) : path_(path), fd_(fd) {}

  std::optional<double> real(const char* name, bool required = false) const {
    vtkDataArray* a = array(name, required);
    if (!a) return std::nullopt;
    if (a->GetDataType() != VTK_DOUBLE) corrupt(path_, std::string("field data '") + name + "' is not Float64");
    const double v = static_cast<const double*>(a->GetVoidPointer(0))[0];
    if (!std::isfinite(v)) corrupt(path_, std::string("field data '") + name + "' is " + exactNumber(v) + ", not finite");
    return v;
  }
  double positive(const char* name) const {
    const double v = *real(name, true);
    if (!(v > 0)) corrupt(path_, std::string("field data '") + name + "' is " + exactNumber(v) + ", not positive");
    return v;
  }
  // A finite time step: positive, or 0 in the initial state (step 0, before any dt was chosen).
  std::optional<double> deltaT(const char* name, std::optional<long> step) const {
    auto v = real(name);
    if (v && !(*v > 0 || (*v == 0 && step.value_or(0) == 0)))
      corrupt(path_, std::string("field data '") + name + "' is " + exactNumber(*v) + ", not a positive time step");
    return v;
  }
  std::optional<std::int64_t> integer(const char* name, std::int64_t min, std::int64_t max, bool required = false) const {
    vtkDataArray* a = array(name, required);
    if (!a) return std::nullopt;
    if (!isInt64(a)) corrupt(path_, std::string("field data '") + name + "' is not Int64");
    std::int64_t v;
    std::memcpy(&v, a->GetVoidPointer(0), sizeof v);
    if (v < min || v > max)
      corrupt(path_, std::string("field data '") + name + "' is " + std::to_string(v) + ", not in " +
                         std::to_string(min) + ".." + std::to_string(max));
    return v;
  }

 private:
  vtkDataArray* array(const char* name, bool required) const {
    vtkDataArray* a = fd_ ? fd_->GetArray(name) : nullptr;
    if (!a) {
      if (required) corrupt(path_, std::string("field data '") + name + "' is missing");
      return nullptr;
    }
    if (a->GetNumberOfTuples() != 1 || a->GetNumberOfComponents() != 1)
      corrupt(path_, std::string("field data '") + name + "' is not a single value");
    return a;
  }
  const std::string& path_;
  vtkFieldData* fd_;
};

// VTK reads the file the pre-scan (VtpLayout.hpp) has passed.
vtkSmartPointer<vtkPolyData> readPolyData(const std::string& path, const VtpLayout& layout) {
  vtkNew<vtkXMLPolyDataReader> r;
  vtkNew<VtkMessages> messages;
  r->AddObserver(vtkCommand::ErrorEvent, messages);
  r->AddObserver(vtkCommand::WarningEvent, messages);
  r->SetReaderErrorObserver(messages);
  r->SetParserErrorObserver(messages);
  r->SetFileName(path.c_str());
  const int ok = r->GetExecutive()->Update();
  if (!ok || !messages->text.empty() || r->GetErrorCode() != 0)
    corrupt(path, messages->text.empty() ? "VTK reader failed" : messages->text);
  vtkSmartPointer<vtkPolyData> pd = r->GetOutput();
  if (!pd) corrupt(path, "no PolyData in file");
  if (pd->GetNumberOfPoints() != layout.points)
    corrupt(path, "VTK read " + std::to_string(pd->GetNumberOfPoints()) + " points, the header states " +
                      std::to_string(layout.points));
  return pd;
}

}  // namespace

template <int D>
void writeVtp(const std::string& path, const ParticleSet<D>& p, const TimeState& s, std::size_t count) {
  const std::size_t first = std::min(count, p.size());
  const vtkIdType n = vtkIdType(first);
  vtkNew<vtkPolyData> pd;

  vtkNew<vtkPoints> points;
  points->SetData(makeArray<D>("position", p.position, first));
  pd->SetPoints(points);

  vtkNew<vtkTypeInt64Array> offsets, connectivity;
  offsets->SetNumberOfTuples(n + 1);
  connectivity->SetNumberOfTuples(n);
  vtkTypeInt64* off = offsets->GetPointer(0);
  vtkTypeInt64* con = connectivity->GetPointer(0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < long(n); ++i) {
    off[i] = i;
    con[i] = i;
  }
  off[n] = n;
  vtkNew<vtkCellArray> verts;
  verts->SetData(offsets, connectivity);
  pd->SetVerts(verts);

  p.forEachField([&](const char* name, const auto& v) {
    if (v.empty() && !ParticleSet<D>::isMandatory(name)) return;
    if (v.size() != p.size())
      throw std::runtime_error("cannot write '" + path + "': field '" + name + "' has " +
                               std::to_string(v.size()) + " values for " + std::to_string(p.size()) + " particles");
    pd->GetPointData()->AddArray(makeArray(name, v, first));
  });

  vtkFieldData* fd = pd->GetFieldData();
  addFieldValue(fd, "mass", p.mass);
  addFieldValue(fd, "rho0", p.rho0);
  addFieldValue(fd, "spacing", p.spacing);
  addFieldValue(fd, "volume", p.volume());
  addFieldValue(fd, "dimension", std::int64_t(D));
  addFieldValue(fd, "time", s.time);
  addFieldValue(fd, "TimeValue", s.time);
  addFieldValue(fd, "timeIndex", std::int64_t(s.step));
  addFieldValue(fd, "deltaT", s.deltaT);
  addFieldValue(fd, "deltaT0", s.deltaT0);
  const ParticleCounts c = countParticles(p, first);
  addFieldValue(fd, "fluidParticles", *c.fluid);
  addFieldValue(fd, "wallParticles", *c.wall);
  addFieldValue(fd, "nextId", c.idLimit);

  fileops::failurePoint("write vtp", path);
  vtkNew<vtkXMLPolyDataWriter> w;
  vtkNew<VtkMessages> messages, pipeline;
  w->AddObserver(vtkCommand::ErrorEvent, messages);
  w->AddObserver(vtkCommand::WarningEvent, messages);
  // The pipeline repeats a failed write as a multi-line dump ("Algorithm ...
  // returned failure for request: ..."): keep it off stderr; the writer's own
  // message says what went wrong.
  w->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipeline);
  w->GetExecutive()->AddObserver(vtkCommand::WarningEvent, pipeline);
  w->SetFileName(path.c_str());
  w->SetInputData(pd);
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();
  w->SetCompressorTypeToNone();
  w->SetHeaderTypeToUInt64();
  errno = 0;
  int ok = w->Write();
  if (!ok || w->GetErrorCode() != 0) {
    int err = errno;
    std::string why = messages->text.empty() ? "VTK writer failed" : messages->text;
    if (err != 0) why += std::string(" (") + std::strerror(err) + ")";
    throw std::runtime_error("cannot write '" + path + "': " + why);
  }
}

template <int D>
ParticleSet<D> readVtp(const std::string& path, VtpTime* t) {
  if (!fileops::isRegularFile(path))
    throw InputError("cannot read particle file '" + path + "': " +
                     (fileops::isDirectory(path) ? std::string("it is a folder") : std::strerror(ENOENT)));
  const VtpLayout layout = scanVtpLayout(path);
  const vtkSmartPointer<vtkPolyData> pd = readPolyData(path, layout);
  const FieldValues f(path, pd->GetFieldData());
  const std::int64_t dimension = *f.integer("dimension", 0, 1000, true);
  if (dimension != D)
    throw InputError("particle file '" + path + "' holds a " + std::to_string(dimension) +
                     "D particle set, but this run is " + std::to_string(D) + "D");

  ParticleSet<D> p;
  p.mass = f.positive("mass");
  p.rho0 = f.positive("rho0");
  p.spacing = f.positive("spacing");
  VtpTime time;
  time.time = f.real("time");
  time.timeValue = f.real("TimeValue");
  time.step = f.integer("timeIndex", 0, std::numeric_limits<long>::max());
  time.deltaT = f.deltaT("deltaT", time.step);
  time.deltaT0 = f.deltaT("deltaT0", time.step);
  if (t) *t = time;

  const vtkIdType n = pd->GetNumberOfPoints();
  if (n > 0) readArray<D>(path, "position", pd->GetPoints()->GetData(), n, p.position);
  vtkPointData* pdata = pd->GetPointData();
  p.forEachField([&](const char* name, auto& v) {
    vtkAbstractArray* raw = pdata->GetAbstractArray(name);
    if (!raw) {
      if (ParticleSet<D>::isMandatory(name)) corrupt(path, std::string("point-data array '") + name + "' is missing");
      return;
    }
    auto* a = vtkDataArray::SafeDownCast(raw);
    if (!a) corrupt(path, std::string("point-data array '") + name + "' is not numeric");
    readArray(path, name, a, n, v);
  });
  // Files written before the counts were kept have dense ids 0..n-1.
  ParticleCounts stated;
  stated.fluid = f.integer("fluidParticles", 0, kMaxParticleId);
  stated.wall = f.integer("wallParticles", 0, kMaxParticleId);
  stated.idLimit = f.integer("nextId", 0, kMaxParticleId).value_or(n);
  checkParticleValues<D>(path, p, stated);
  p.nextId = stated.idLimit;
  return p;
}

template void writeVtp<2>(const std::string&, const ParticleSet<2>&, const TimeState&, std::size_t);
template void writeVtp<3>(const std::string&, const ParticleSet<3>&, const TimeState&, std::size_t);
template ParticleSet<2> readVtp<2>(const std::string&, VtpTime*);
template ParticleSet<3> readVtp<3>(const std::string&, VtpTime*);

}  // namespace shizuku
