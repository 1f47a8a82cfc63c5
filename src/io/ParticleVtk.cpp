#include "io/ParticleVtk.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/AtomicFile.hpp"
#include "sph/ParticleSet.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationDoubleVectorKey.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTypeInt64Array.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <algorithm>
#include <limits>
#include <numeric>
#include <string>
#include <system_error>
#include <type_traits>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

namespace poro {

namespace fs = std::filesystem;

namespace {

// Vec3 and Mat3 are unaligned Eigen types, so a std::vector of them is a flat array of doubles.
static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(sizeof(Mat3) == 9 * sizeof(double), "Mat3 must be nine packed doubles");

const char* const setNameKey = "setName";
const char* const kindKey = "kind";

/// Captures the error and warning messages VTK objects emit, which would otherwise go to stderr through
/// vtkOutputWindow and leave the caller with nothing but a failed Update().
class VtkMessages {
public:
  VtkMessages() {
    command_->SetClientData(this);
    command_->SetCallback(&VtkMessages::record);
  }
  VtkMessages(const VtkMessages&) = delete;
  VtkMessages& operator=(const VtkMessages&) = delete;

  vtkCommand* command() { return command_; }
  void observe(vtkObject* object) {
    if (!object) return;
    object->AddObserver(vtkCommand::ErrorEvent, command_);
    object->AddObserver(vtkCommand::WarningEvent, command_);
  }
  bool hasErrors() const { return !errors_.empty(); }
  /// The first error: later ones are usually consequences ("algorithm returned failure").
  std::string firstError() const { return errors_.empty() ? std::string() : errors_.front(); }

private:
  static void record(vtkObject*, unsigned long event, void* clientData, void* callData) {
    auto* self = static_cast<VtkMessages*>(clientData);
    std::string message = callData ? static_cast<const char*>(callData) : "unknown VTK error";
    // VTK prefixes "vtkClassName (0x55d0...): "; the user needs only the text.
    if (const auto pos = message.find("): "); pos != std::string::npos) message.erase(0, pos + 3);
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back()))) message.pop_back();
    // Warnings are neither fatal nor worth stderr noise in the middle of a run; drop them.
    if (event == vtkCommand::ErrorEvent) self->errors_.push_back(message);
  }

  vtkNew<vtkCallbackCommand> command_;
  std::vector<std::string> errors_;
};

// ---------------------------------------------------------------------------------------------- write

/// Wraps `values` (count tuples of `components` doubles) without copying; the writer only reads it.
vtkSmartPointer<vtkDoubleArray> wrapDoubles(const char* name, const double* values, std::size_t count,
                                            int components) {
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  if (count == 0) return array;
  // save=1: VTK must not free memory the ParticleSet owns.
  array->SetArray(const_cast<double*>(values), static_cast<vtkIdType>(count) * components, 1);
  return array;
}

vtkSmartPointer<vtkDataArray> toVtk(const ParticleSet& set, const ParticleSet::FieldInfo& info) {
  const std::size_t n = set.size();
  switch (info.type) {
  case FieldType::Real: return wrapDoubles(info.name.c_str(), set.real(info.name).data(), n, 1);
  case FieldType::Vec3: {
    const auto& v = set.vec3(info.name);
    return wrapDoubles(info.name.c_str(), n ? v.front().data() : nullptr, n, 3);
  }
  case FieldType::Mat3: {
    // Eigen stores column-major; the file is row-major (xx xy xz yx ...), as ParaView's tensor display expects.
    const auto& m = set.mat3(info.name);
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(info.name.c_str());
    array->SetNumberOfComponents(9);
    array->SetNumberOfTuples(static_cast<vtkIdType>(n));
    double* out = array->GetPointer(0);
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out[9 * i + 3 * r + c] = m[i](r, c);
    return array;
  }
  case FieldType::Int: {
    const auto& values = set.integer(info.name);
    auto array = vtkSmartPointer<vtkTypeInt64Array>::New();
    array->SetName(info.name.c_str());
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i < n; ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
    return array;
  }
  }
  return nullptr;
}

/// Works around VTK 9.1's ascii writer: it stores the cached L2-norm range of multi-component arrays as an
/// <InformationKey> printed with plain `<<`, so an infinite norm (inf values, or components near DBL_MAX
/// whose norm overflows) comes out as "inf", which vtkXMLReader then refuses. Presetting a finite
/// range keeps the file readable; only that cached range (a display hint) is clamped, never the data.
void presetFiniteNormRange(vtkDoubleArray* array) {
  const int components = array->GetNumberOfComponents();
  const vtkIdType tuples = array->GetNumberOfTuples();
  if (components < 2 || tuples == 0) return;
  // Printed with ~11 digits, so stay clear of DBL_MAX, which would round up past it.
  constexpr double limit = 1e308;
  double lo = limit;
  double hi = 0.0;
  bool clamped = false;
  const double* values = array->GetPointer(0);
  for (vtkIdType t = 0; t < tuples; ++t) {
    double sum = 0.0;
    for (int c = 0; c < components; ++c) sum += values[t * components + c] * values[t * components + c];
    const double norm = std::sqrt(sum);
    if (std::isnan(norm)) continue; // VTK skips NaN tuples too
    if (!(norm <= limit)) clamped = true;
    lo = std::min(lo, std::min(norm, limit));
    hi = std::max(hi, std::min(norm, limit));
  }
  if (!clamped) return; // VTK's own range prints fine
  const double range[2] = {lo, hi};
  array->GetInformation()->Set(vtkDataArray::L2_NORM_RANGE(), range, 2);
}

/// Name of the first written field holding NaN or inf, or "".
std::string firstNonFiniteOutputField(const ParticleSet& set) {
  for (const auto& info : set.fields()) {
    if ((info.role & Output) == 0) continue;
    std::size_t count = 0;
    const double* values = nullptr;
    switch (info.type) {
    case FieldType::Real: count = set.size(); values = set.real(info.name).data(); break;
    case FieldType::Vec3: count = 3 * set.size(); values = count ? set.vec3(info.name).front().data() : nullptr; break;
    case FieldType::Mat3: count = 9 * set.size(); values = count ? set.mat3(info.name).front().data() : nullptr; break;
    case FieldType::Int: break;
    }
    for (std::size_t k = 0; k < count; ++k)
      if (!std::isfinite(values[k])) return info.name;
  }
  return {};
}

void addString(vtkFieldData* data, const char* name, const std::string& value) {
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  data->AddArray(array);
}

vtkSmartPointer<vtkPolyData> toPolyData(const ParticleSet& set) {
  const std::size_t n = set.size();
  auto poly = vtkSmartPointer<vtkPolyData>::New();

  vtkNew<vtkPoints> points;
  points->SetData(wrapDoubles("Points", n ? set.x().front().data() : nullptr, n, 3));
  poly->SetPoints(points);

  // One VTK_VERTEX per particle: without cells ParaView draws nothing in Surface representation.
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType{0});
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(1, connectivity);
  poly->SetVerts(vertices);

  for (const auto& info : set.fields()) {
    if ((info.role & Output) == 0 || info.name == field::x) continue;
    poly->GetPointData()->AddArray(toVtk(set, info));
  }

  addString(poly->GetFieldData(), setNameKey, set.name());
  addString(poly->GetFieldData(), kindKey, toString(set.kind()));
  return poly;
}

/// Text for a writer's error code. Codes below FirstVTKErrorCode are errno values. (vtkErrorCode's own
/// GetStringFromErrorCode lives in CommonMisc, which poro_io does not link.)
std::string errorCodeText(unsigned long code) {
  if (code == vtkErrorCode::NoError) return {};
  if (code < vtkErrorCode::FirstVTKErrorCode) return std::strerror(static_cast<int>(code));
  switch (code) {
  case vtkErrorCode::CannotOpenFileError: return "cannot open file";
  case vtkErrorCode::OutOfDiskSpaceError: return "out of disk space";
  case vtkErrorCode::NoFileNameError: return "no file name";
  default: return "VTK error code " + std::to_string(code);
  }
}

[[noreturn]] void throwOutput(const fs::path& file, const std::string& what) {
  throw OutputError(file.string() + ": " + what);
}

/// Writes `set` with vtkXMLPolyDataWriter to `temporary`; errors name the final `file`.
void writeVtk(const ParticleSet& set, const fs::path& temporary, const fs::path& file, bool binary) {
  const vtkSmartPointer<vtkPolyData> poly = toPolyData(set);
  VtkMessages messages; // declared before the writer so it outlives every callback
  vtkNew<vtkXMLPolyDataWriter> writer;
  messages.observe(writer);
  messages.observe(writer->GetExecutive());
  writer->SetInputData(poly);
  writer->SetFileName(temporary.c_str());
  writer->SetHeaderTypeToUInt64(); // sets beyond 2^32 bytes per array
  writer->SetIdTypeToInt64();
  if (binary) {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff(); // raw bytes: no base64 inflation
    writer->SetCompressorTypeToZLib();
  } else {
    writer->SetDataModeToAscii();
    writer->SetCompressorTypeToNone();
    presetFiniteNormRange(vtkDoubleArray::SafeDownCast(poly->GetPoints()->GetData()));
    for (int k = 0; k < poly->GetPointData()->GetNumberOfArrays(); ++k)
      if (auto* array = vtkDoubleArray::SafeDownCast(poly->GetPointData()->GetArray(k))) presetFiniteNormRange(array);
  }

  const int ok = writer->Write();
  const unsigned long code = writer->GetErrorCode();
  if (!ok || code != vtkErrorCode::NoError || messages.hasErrors()) {
    std::string reason = messages.firstError();
    const std::string codeText = errorCodeText(code);
    if (!codeText.empty()) reason = codeText + (reason.empty() ? "" : ": " + reason);
    throwOutput(file, "cannot write VTK file (" + (reason.empty() ? std::string("unknown error") : reason) + ")");
  }
}

// ----------------------------------------------------------------------------------------------- read

[[noreturn]] void throwInput(const fs::path& file, const std::string& what) {
  throw InputError(file.string() + ": " + what);
}

bool isFloating(int vtkType) { return vtkType == VTK_FLOAT || vtkType == VTK_DOUBLE; }

bool isIntegral(int vtkType) {
  switch (vtkType) {
  case VTK_CHAR: case VTK_SIGNED_CHAR: case VTK_UNSIGNED_CHAR: case VTK_SHORT: case VTK_UNSIGNED_SHORT:
  case VTK_INT: case VTK_UNSIGNED_INT: case VTK_LONG: case VTK_UNSIGNED_LONG: case VTK_LONG_LONG:
  case VTK_UNSIGNED_LONG_LONG: case VTK_ID_TYPE:
    return true;
  default: return false;
  }
}

const char* typeName(FieldType type) {
  switch (type) {
  case FieldType::Real: return "Real (1 floating-point component)";
  case FieldType::Vec3: return "Vec3 (3 floating-point components)";
  case FieldType::Mat3: return "Mat3 (9 floating-point components)";
  case FieldType::Int: return "Int (1 integer component)";
  }
  return "?";
}

/// Calls fn(const T* values) with the array's raw values; arrays from the XML reader are AOS.
template <class Fn>
void withValues(vtkDataArray* array, Fn&& fn) {
  switch (array->GetDataType()) {
    vtkTemplateMacro(fn(static_cast<const VTK_TT*>(array->GetVoidPointer(0))));
  default: break;
  }
}

/// One point-data array to copy into the set, checked before the set is touched.
struct Transfer {
  vtkDataArray* array;
  std::string name;
  FieldType type;
};

/// Index of the first tuple with a NaN or inf component, or -1.
vtkIdType firstNonFinite(vtkDataArray* array) {
  vtkIdType bad = -1;
  const vtkIdType count = array->GetNumberOfValues();
  const int components = array->GetNumberOfComponents();
  withValues(array, [&](const auto* values) {
    using T = std::remove_const_t<std::remove_pointer_t<decltype(values)>>;
    if constexpr (std::is_floating_point_v<T>) {
      for (vtkIdType k = 0; k < count; ++k)
        if (!std::isfinite(values[k])) {
          bad = k / components;
          return;
        }
    }
  });
  return bad;
}

/// Index of the first value an int64 cannot hold (only UInt64 arrays can have one), or -1.
vtkIdType firstOutOfInt64(vtkDataArray* array) {
  vtkIdType bad = -1;
  const vtkIdType count = array->GetNumberOfValues();
  withValues(array, [&](const auto* values) {
    using T = std::remove_const_t<std::remove_pointer_t<decltype(values)>>;
    if constexpr (std::is_integral_v<T> && std::is_unsigned_v<T> && sizeof(T) >= sizeof(std::int64_t)) {
      for (vtkIdType k = 0; k < count; ++k)
        if (values[k] > static_cast<T>(std::numeric_limits<std::int64_t>::max())) {
          bad = k;
          return;
        }
    }
  });
  return bad;
}

/// Copies `count` tuples of `components` values into the flat double storage `out`.
void copyToDoubles(vtkDataArray* array, double* out) {
  const vtkIdType count = array->GetNumberOfValues();
  withValues(array, [&](const auto* values) {
    for (vtkIdType k = 0; k < count; ++k) out[k] = static_cast<double>(values[k]);
  });
}

void copyTo(ParticleSet& set, const Transfer& t) {
  const std::size_t n = set.size();
  // add* raises a role that is lower than requested; keep an existing field's role (even Scratch).
  const auto* existing = set.info(t.name);
  const FieldRole role = existing ? existing->role : Output;
  switch (t.type) {
  case FieldType::Real: {
    auto& field = set.addReal(t.name, role);
    if (n) copyToDoubles(t.array, field.data());
    break;
  }
  case FieldType::Vec3: {
    auto& field = set.addVec3(t.name, role);
    if (n) copyToDoubles(t.array, field.front().data());
    break;
  }
  case FieldType::Mat3: {
    auto& field = set.addMat3(t.name, role);
    std::vector<double> rowMajor(9 * n);
    if (n) copyToDoubles(t.array, rowMajor.data());
    for (std::size_t i = 0; i < n; ++i)
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) field[i](r, c) = rowMajor[9 * i + 3 * r + c];
    break;
  }
  case FieldType::Int: {
    auto& field = set.addInt(t.name, role);
    withValues(t.array, [&](const auto* values) {
      for (std::size_t i = 0; i < n; ++i) field[i] = static_cast<std::int64_t>(values[i]);
    });
    break;
  }
  }
}

/// The single string of a field-data string array, or "" when absent.
std::string fieldString(vtkFieldData* data, const char* name) {
  auto* array = vtkStringArray::SafeDownCast(data ? data->GetAbstractArray(name) : nullptr);
  if (!array || array->GetNumberOfValues() < 1) return {};
  return array->GetValue(0);
}

/// Checks that `file` can be opened, so the common mistakes get the OS's words, not VTK's.
void checkReadable(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throwInput(file, std::string("cannot read (") + std::strerror(EISDIR) + ")");
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throwInput(file, std::string("cannot open (") + std::strerror(errno) + ")");
  ::close(fd);
}

} // namespace

void writeParticleSet(const ParticleSet& set, const fs::path& file, bool binary) {
  const fs::path temporary = temporarySibling(file);
  {
    // Create the file ourselves first: a missing or read-only directory then gets the OS's reason,
    // which vtkXMLWriter does not report.
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) throwOutput(file, std::string("cannot create file (") + std::strerror(errno) + ")");
    ::close(fd);
  }

  if (!binary) {
    // VTK 9.1 prints NaN and inf in ascii files but its reader (and so ParaView) rejects them; a diverged
    // state is exactly what one wants to look at, so keep it readable.
    if (const std::string bad = firstNonFiniteOutputField(set); !bad.empty()) {
      log::warning(file.string() + ": field '" + bad +
                   "' holds NaN or infinite values, which VTK cannot read back from ascii; writing binary");
      binary = true;
    }
  }

  try {
    writeVtk(set, temporary, file, binary);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  commitTemporaryFile(temporary, file);
}

void readParticleSet(ParticleSet& set, const fs::path& file) {
  checkReadable(file);

  VtkMessages messages; // declared before the reader so it outlives every callback
  vtkNew<vtkXMLPolyDataReader> reader;
  messages.observe(reader);
  messages.observe(reader->GetExecutive());
  reader->SetReaderErrorObserver(messages.command());
  reader->SetParserErrorObserver(messages.command());
  reader->SetFileName(file.c_str());
  reader->Update();

  vtkPolyData* poly = reader->GetOutput();
  if (messages.hasErrors() || !poly) {
    throwInput(file, "not a readable VTK PolyData file (truncated or corrupt?)" +
                         (messages.hasErrors() ? ": " + messages.firstError() : std::string()));
  }

  const std::string kind = fieldString(poly->GetFieldData(), kindKey);
  if (!kind.empty() && kind != toString(set.kind()))
    throwInput(file, "holds a '" + kind + "' particle set, expected '" + toString(set.kind()) + "'");

  const vtkIdType n = poly->GetNumberOfPoints();
  vtkDataArray* coordinates = poly->GetPoints() ? poly->GetPoints()->GetData() : nullptr;
  if (n > 0 && (!coordinates || !isFloating(coordinates->GetDataType()) || coordinates->GetNumberOfComponents() != 3))
    throwInput(file, "points are not 3-component floating-point coordinates");
  if (n > 0) {
    const auto* xInfo = set.info(field::x);
    if (xInfo && (xInfo->role & Restart) == Restart) {
      if (const vtkIdType bad = firstNonFinite(coordinates); bad >= 0)
        throwInput(file, "point coordinates: particle " + std::to_string(bad) + " has a NaN or infinite value");
    }
  }

  // Validate everything before touching the set, so a bad file leaves it unchanged.
  std::vector<Transfer> transfers;
  vtkPointData* pointData = poly->GetPointData();
  for (int k = 0; k < pointData->GetNumberOfArrays(); ++k) {
    vtkAbstractArray* abstract = pointData->GetAbstractArray(k);
    if (!abstract->GetName() || !*abstract->GetName())
      throwInput(file, "point-data array #" + std::to_string(k) + " has no name");
    const std::string name = abstract->GetName();
    const std::string quoted = "array '" + name + "'";
    auto* array = vtkDataArray::SafeDownCast(abstract);
    if (!array) throwInput(file, quoted + " is not numeric (" + abstract->GetClassName() + ")");
    if (name == field::x) throwInput(file, quoted + " clashes with the point coordinates, which are field 'x'");
    if (array->GetNumberOfTuples() != n)
      throwInput(file, quoted + " has " + std::to_string(array->GetNumberOfTuples()) + " values, expected " +
                           std::to_string(n) + " (one per point)");

    const int components = array->GetNumberOfComponents();
    const int dataType = array->GetDataType();
    FieldType type;
    if (isIntegral(dataType) && components == 1) type = FieldType::Int;
    else if (isFloating(dataType) && components == 1) type = FieldType::Real;
    else if (isFloating(dataType) && components == 3) type = FieldType::Vec3;
    else if (isFloating(dataType) && components == 9) type = FieldType::Mat3;
    else
      throwInput(file, quoted + " has " + std::to_string(components) + " component(s) of type " +
                           array->GetDataTypeAsString() +
                           "; expected 1 integer or 1, 3 or 9 floating-point components");

    const auto* existing = set.info(name);
    if (existing && existing->type != type)
      throwInput(file, quoted + " holds " + typeName(type) + " values, but field '" + name + "' of set '" +
                           set.name() + "' is " + typeName(existing->type));
    if (type == FieldType::Int) {
      if (const vtkIdType bad = firstOutOfInt64(array); bad >= 0)
        throwInput(file, quoted + ": particle " + std::to_string(bad) + " has a value beyond the Int64 range");
    } else if (existing && (existing->role & Restart) == Restart) {
      // A restart field feeds the next step directly; NaN would only surface as a diverged solve.
      if (const vtkIdType bad = firstNonFinite(array); bad >= 0)
        throwInput(file, quoted + ": particle " + std::to_string(bad) +
                             " has a NaN or infinite value in a restart field");
    }
    transfers.push_back({array, name, type});
  }

  // Resize through zero so fields absent from the file read as zero rather than stale values.
  set.resize(0);
  set.resize(static_cast<std::size_t>(n));
  if (n > 0) copyToDoubles(coordinates, set.x().front().data());
  for (const auto& t : transfers) copyTo(set, t);
}

} // namespace poro
