#include "io/ParticleVtk.hpp"

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "io/AtomicFile.hpp"
#include "sph/ParticleSet.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataCompressor.h>
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
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <new>
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

/// Doubles per particle of a field of `type` (0 for Int).
int doublesPerParticle(FieldType type) {
  switch (type) {
  case FieldType::Real:
    return 1;
  case FieldType::Vec3:
    return 3;
  case FieldType::Mat3:
    return 9;
  case FieldType::Int:
    return 0;
  }
  return 0;
}

/// The values of Real, Vec3 or Mat3 field `info` of `set` as a flat array of doubles (Mat3 column-major); nullptr
/// for an Int field or an empty set.
const double* doublesOf(const ParticleSet& set, const ParticleSet::FieldInfo& info) {
  if (set.size() == 0 || !set.has(info.name)) return nullptr;
  switch (info.type) {
  case FieldType::Real:
    return set.real(info.name).data();
  case FieldType::Vec3:
    return set.vec3(info.name).front().data();
  case FieldType::Mat3:
    return set.mat3(info.name).front().data();
  case FieldType::Int:
    return nullptr;
  }
  return nullptr;
}

/// Field `info` of every part, one after the other, as the file's array (`count` tuples in all). A Real or Vec3
/// field of a single part is wrapped, not copied.
vtkSmartPointer<vtkDataArray> toVtk(const ParticleFile& contents, const ParticleSet::FieldInfo& info, const char* name,
                                    std::size_t count) {
  switch (info.type) {
  case FieldType::Real:
  case FieldType::Vec3: {
    const int components = doublesPerParticle(info.type);
    if (contents.parts.size() == 1)
      return wrapDoubles(name, doublesOf(*contents.parts.front(), info), count, components);
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(count));
    double* out = array->GetPointer(0);
    for (const ParticleSet* part : contents.parts) {
      const std::size_t values = components * part->size();
      const double* from = doublesOf(*part, info);
      if (from)
        std::copy_n(from, values, out);
      else
        std::fill_n(out, values, 0.0);
      out += values;
    }
    return array;
  }
  case FieldType::Mat3: {
    // Eigen stores column-major; the file is row-major (xx xy xz yx ...), as ParaView's tensor display expects.
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name);
    array->SetNumberOfComponents(9);
    array->SetNumberOfTuples(static_cast<vtkIdType>(count));
    double* out = array->GetPointer(0);
    for (const ParticleSet* part : contents.parts) {
      if (!part->has(info.name)) {
        out = std::fill_n(out, 9 * part->size(), 0.0);
        continue;
      }
      for (const Mat3& m : part->mat3(info.name))
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) *out++ = m(r, c);
    }
    return array;
  }
  case FieldType::Int: {
    auto array = vtkSmartPointer<vtkTypeInt64Array>::New();
    array->SetName(name);
    array->SetNumberOfComponents(1);
    array->SetNumberOfTuples(static_cast<vtkIdType>(count));
    vtkTypeInt64* out = array->GetPointer(0);
    for (const ParticleSet* part : contents.parts) {
      if (!part->has(info.name)) {
        out = std::fill_n(out, part->size(), vtkTypeInt64{0});
        continue;
      }
      for (const std::int64_t value : part->integer(info.name)) *out++ = value;
    }
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
std::string firstNonFiniteOutputField(const ParticleFile& contents) {
  for (const auto& info : contents.fields)
    for (const ParticleSet* part : contents.parts) {
      const double* values = doublesOf(*part, info);
      if (!values) continue; // an Int field, an empty part, or one written as zeros
      const std::size_t count = doublesPerParticle(info.type) * part->size();
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

vtkSmartPointer<vtkPolyData> toPolyData(const ParticleFile& contents) {
  std::size_t n = 0;
  for (const ParticleSet* part : contents.parts) n += part->size();
  auto poly = vtkSmartPointer<vtkPolyData>::New();

  vtkNew<vtkPoints> points;
  points->SetData(toVtk(contents, {field::x, FieldType::Vec3, Restart}, "Points", n));
  poly->SetPoints(points);

  // One VTK_VERTEX per particle: without cells ParaView draws nothing in Surface representation.
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(n));
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType{0});
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(1, connectivity);
  poly->SetVerts(vertices);

  for (const auto& info : contents.fields)
    if (info.name != field::x) poly->GetPointData()->AddArray(toVtk(contents, info, info.name.c_str(), n));

  addString(poly->GetFieldData(), setNameKey, contents.name);
  addString(poly->GetFieldData(), kindKey, toString(contents.kind));
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

/// Writes `contents` with vtkXMLPolyDataWriter to `temporary`; errors name the final `file`.
void writeVtk(const ParticleFile& contents, const fs::path& temporary, const fs::path& file, bool binary) {
  const vtkSmartPointer<vtkPolyData> poly = toPolyData(contents);
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
    // zlib's fastest level: particle doubles barely compress (the Seep's porous.vtp at r = 1 cm: 18.44 MB at
    // level 1, 18.34 MB at VTK's default 5), and level 1 takes 0.63 of the time; the writes run on one thread.
    writer->SetCompressionLevel(1);
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

/// The file's first and last bytes: an empty file, one that is not XML at all and one cut short (a full disk,
/// a copy interrupted) get a message that says so instead of the XML parser's byte index.
void checkEnds(const fs::path& file) {
  const auto size = fs::file_size(file);
  if (size == 0) throwInput(file, "not a readable VTK PolyData file: the file is empty");
  std::ifstream in(file, std::ios::binary);
  std::string head(static_cast<std::size_t>(std::min<std::uintmax_t>(size, 64)), '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  const std::size_t start = head.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0; // a UTF-8 byte-order mark
  const std::size_t first = head.find_first_not_of(" \t\r\n", start);
  if (first == std::string::npos || (head.compare(first, 5, "<?xml") != 0 && head.compare(first, 8, "<VTKFile") != 0))
    throwInput(file, "not a readable VTK PolyData file: it does not start with <?xml or <VTKFile (not a VTK XML file)");
  // The closing tag must be near the end; XML allows a trailing comment, so look at the last 4 KB, not the last bytes.
  const std::uintmax_t tailSize = std::min<std::uintmax_t>(size, 4096);
  std::string tail(static_cast<std::size_t>(tailSize), '\0');
  in.seekg(static_cast<std::streamoff>(size - tailSize));
  in.read(tail.data(), static_cast<std::streamsize>(tail.size()));
  if (tail.find("</VTKFile>") == std::string::npos)
    throwInput(file, "not a readable VTK PolyData file: it does not end with </VTKFile> (truncated?)");
}

/// One DataArray element of a piece (point data or the coordinates), as the XML header describes it.
struct ArrayElement {
  vtkTypeInt64 offset = 0;  ///< byte index of the element's '<'
  std::string name;         ///< Name attribute; "Points" for the coordinates
  bool coordinates = false; ///< the Points array
  std::string type;         ///< type attribute: Float64, Int64, ...
  bool ascii = false;       ///< format="ascii": the values are checked here, before VTK reads them
  long long tuples = 0;     ///< NumberOfPoints of its piece
  long long components = 1; ///< NumberOfComponents
  int line = 0;             ///< 1-based line of the element, filled by scanArrays
};

bool isNumericType(const std::string& type) {
  static const char* const names[] = {"Float32", "Float64", "Int8",   "UInt8", "Int16",
                                      "UInt16",  "Int32",   "UInt32", "Int64", "UInt64"};
  return std::find(std::begin(names), std::end(names), type) != std::end(names);
}

/// "array 'v'" or "array 'Points' of point coordinates".
std::string describe(const ArrayElement& a) {
  return "array '" + a.name + "'" + (a.coordinates ? " of point coordinates" : "");
}

/// A whole-number attribute of the XML header (`fallback` when absent).
long long integerAttribute(const fs::path& file, vtkXMLDataElement* element, const char* name, long long fallback) {
  const char* text = element->GetAttribute(name);
  if (!text) return fallback;
  errno = 0;
  char* end = nullptr;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || errno == ERANGE)
    throwInput(file, std::string(element->GetName()) + " attribute " + name + "=\"" + text +
                         "\" is not a whole number that fits in 64 bits");
  return value;
}

/// Every DataArray of every piece's PointData and Points. Refuses a point count that is negative or larger than
/// the file could hold: VTK would allocate it before finding the data short.
std::vector<ArrayElement> describeArrays(const fs::path& file, vtkXMLDataParser* parser) {
  std::vector<ArrayElement> arrays;
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* poly = root ? root->FindNestedElementWithName("PolyData") : nullptr;
  if (!poly) return arrays; // VTK has said what is wrong
  const double size = static_cast<double>(fs::file_size(file));
  for (int p = 0; p < poly->GetNumberOfNestedElements(); ++p) {
    vtkXMLDataElement* piece = poly->GetNestedElement(p);
    if (std::strcmp(piece->GetName(), "Piece") != 0) continue;
    const long long n = integerAttribute(file, piece, "NumberOfPoints", 0);
    if (n < 0) throwInput(file, "Piece NumberOfPoints=\"" + std::to_string(n) + "\" is negative");
    // 24 bytes of coordinates per point, and zlib compresses by at most 1032:1.
    if (24.0 * static_cast<double>(n) > 1032.0 * size + 1e6)
      throwInput(file, "Piece NumberOfPoints=\"" + std::to_string(n) + "\" cannot be right for a file of " +
                           std::to_string(static_cast<long long>(size)) +
                           " bytes (the coordinates alone need 24 bytes per point, compressed at most 1032:1); "
                           "the file is corrupt");
    for (const char* group : {"PointData", "Points"}) {
      vtkXMLDataElement* data = piece->FindNestedElementWithName(group);
      for (int k = 0; data && k < data->GetNumberOfNestedElements(); ++k) {
        vtkXMLDataElement* e = data->GetNestedElement(k);
        if (std::strcmp(e->GetName(), "DataArray") != 0) continue;
        ArrayElement a;
        a.offset = e->GetXMLByteIndex();
        a.coordinates = std::strcmp(group, "Points") == 0;
        a.name = e->GetAttribute("Name") ? e->GetAttribute("Name") : "";
        a.type = e->GetAttribute("type") ? e->GetAttribute("type") : "";
        a.ascii = e->GetAttribute("format") && std::strcmp(e->GetAttribute("format"), "ascii") == 0 &&
                  isNumericType(a.type); // String arrays are VTK's to read
        a.tuples = n;
        a.components = integerAttribute(file, e, "NumberOfComponents", 1);
        if (a.components < 1 || a.components > 9)
          throwInput(file,
                     describe(a) + ": NumberOfComponents=\"" + std::to_string(a.components) + "\"; expected 1 to 9");
        arrays.push_back(a);
      }
    }
  }
  return arrays;
}

/// Why `token` is not a value of VTK type `type`, or "" when it is one. Decimal numbers only, as VTK's ascii
/// reader takes them; nan and inf are numbers here (the restart check below names them).
std::string badValue(const std::string& token, const std::string& type) {
  const bool floating = type == "Float32" || type == "Float64";
  const char* text = token.c_str();
  char* end = nullptr;
  errno = 0;
  if (floating) {
    std::string word = token;
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.erase(0, 1);
    if (word == "nan" || word == "inf" || word == "infinity") return {};
    if (token.find_first_of("xXpP") != std::string::npos) return "is not a decimal number";
    const double v = std::strtod(text, &end);
    if (end == text || *end != '\0') return "is not a number";
    if (errno == ERANGE && std::fabs(v) > 1.0) return "is out of the range of " + type;
    if (type == "Float32" && std::fabs(v) > FLT_MAX) return "is out of the range of Float32";
    return {};
  }
  if (token.find_first_not_of("+-0123456789") != std::string::npos ||
      token.find_first_of("0123456789") == std::string::npos)
    return "is not a whole number (the array is " + type + ")";
  static const std::map<std::string, std::pair<long double, long double>> ranges = {
      {"Int8", {-128.0L, 127.0L}},
      {"UInt8", {0.0L, 255.0L}},
      {"Int16", {-32768.0L, 32767.0L}},
      {"UInt16", {0.0L, 65535.0L}},
      {"Int32", {-2147483648.0L, 2147483647.0L}},
      {"UInt32", {0.0L, 4294967295.0L}},
      {"Int64", {-9223372036854775808.0L, 9223372036854775807.0L}},
      {"UInt64", {0.0L, 18446744073709551615.0L}}};
  const long double v = std::strtold(text, &end);
  if (end == text || *end != '\0') return "is not a whole number (the array is " + type + ")";
  const auto range = ranges.find(type);
  if (range != ranges.end() && (v < range->second.first || v > range->second.second))
    return "is out of the range of " + type;
  return {};
}

/// One pass over the file: the line of every array element, and for ascii arrays the count and form of their values,
/// so that a hand-edited file gets "file:line: array 'v' holds 8 values, expected 9" rather than VTK's "may be too
/// short" (or nothing at all when an array is too long). Costs one more read of an ascii file; binary files are
/// read only up to their last array element (VTK checks their block sizes).
void scanArrays(const fs::path& file, std::vector<ArrayElement>& arrays) {
  std::sort(arrays.begin(), arrays.end(),
            [](const ArrayElement& a, const ArrayElement& b) { return a.offset < b.offset; });
  std::ifstream in(file, std::ios::binary);
  std::vector<char> buffer(1 << 16);
  std::size_t used = 0, filled = 0;
  vtkTypeInt64 position = 0;
  int line = 1;
  auto next = [&]() -> int {
    if (used == filled) {
      in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
      filled = static_cast<std::size_t>(in.gcount());
      used = 0;
      if (filled == 0) return EOF;
    }
    const char c = buffer[used++];
    ++position;
    if (c == '\n') ++line;
    return static_cast<unsigned char>(c);
  };
  const std::string name = file.string();
  for (ArrayElement& a : arrays) {
    while (position < a.offset)
      if (next() == EOF) return;
    a.line = line;
    if (!a.ascii) continue;
    // The rest of the start tag (attribute values may hold '>'); a self-closing tag holds no values.
    int c = 0, previous = 0;
    char quote = 0;
    while ((c = next()) != EOF) {
      if (quote) {
        if (c == quote) quote = 0;
      } else if (c == '"' || c == '\'') {
        quote = static_cast<char>(c);
      } else if (c == '>') {
        break;
      }
      previous = c;
    }
    const long long expected = a.tuples * a.components;
    long long count = 0;
    std::string token;
    int tokenLine = line;
    auto finish = [&] {
      if (token.empty()) return;
      if (const std::string why = badValue(token, a.type); !why.empty() && count < expected)
        throw InputError(name + ":" + std::to_string(tokenLine) + ": " + describe(a) + ": value '" + token +
                         "' (particle " + std::to_string(count / a.components) + ") " + why);
      ++count;
      token.clear();
    };
    if (previous != '/') {
      while ((c = next()) != EOF && c != '<') {
        if (std::isspace(c)) {
          finish();
        } else {
          if (token.empty()) tokenLine = line;
          if (token.size() < 40) token += static_cast<char>(c); // a runaway token is named by its start
        }
      }
      finish();
    }
    if (count != expected)
      throw InputError(name + ":" + std::to_string(a.line) + ": " + describe(a) + " holds " + std::to_string(count) +
                       " values, expected " + std::to_string(expected) + " (NumberOfPoints " +
                       std::to_string(a.tuples) + " times " + std::to_string(a.components) +
                       (a.components == 1 ? " component)" : " components)"));
  }
}

} // namespace

ParticleFile particleFileOf(const ParticleSet& set) {
  ParticleFile contents{set.name(), set.kind(), {&set}, {}};
  for (const auto& info : set.fields())
    if (info.role & Output) contents.fields.push_back(info);
  return contents;
}

void writeParticleSet(const ParticleSet& set, const fs::path& file, bool binary) {
  writeParticleFile(particleFileOf(set), file, binary);
}

void writeParticleFile(const ParticleFile& contents, const fs::path& file, bool binary) {
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
    if (const std::string bad = firstNonFiniteOutputField(contents); !bad.empty()) {
      log::warning(file.string() + ": field '" + bad +
                   "' holds NaN or infinite values, which VTK cannot read back from ascii; writing binary");
      binary = true;
    }
  }

  try {
    writeVtk(contents, temporary, file, binary);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  commitTemporaryFile(temporary, file);
}

std::vector<std::string> readParticleSet(ParticleSet& set, const fs::path& file) {
  checkReadable(file);
  checkEnds(file);

  VtkMessages messages; // declared before the reader so it outlives every callback
  vtkNew<vtkXMLPolyDataReader> reader;
  messages.observe(reader);
  messages.observe(reader->GetExecutive());
  reader->SetReaderErrorObserver(messages.command());
  reader->SetParserErrorObserver(messages.command());
  reader->SetFileName(file.c_str());
  auto failIfErrors = [&] {
    if (messages.hasErrors())
      throwInput(file, "not a readable VTK PolyData file (truncated or corrupt?): " + messages.firstError());
  };

  // The XML header first: sizes and ascii values are checked before VTK allocates and parses the arrays.
  reader->UpdateInformation();
  failIfErrors();
  if (vtkXMLDataParser* parser = reader->GetXMLParser()) messages.observe(parser->GetCompressor()); // zlib errors
  std::vector<ArrayElement> elements = describeArrays(file, reader->GetXMLParser());
  scanArrays(file, elements);
  std::map<std::string, std::string> at; // array name -> "file:line: "
  for (const ArrayElement& e : elements)
    at[e.coordinates ? std::string() : e.name] = file.string() + ":" + std::to_string(e.line) + ": ";
  auto where = [&](const std::string& name) {
    const auto it = at.find(name);
    return it != at.end() ? it->second : file.string() + ": ";
  };

  try {
    reader->Update();
  } catch (const std::bad_alloc&) {
    // A corrupt size in a binary block header: VTK allocates what it says before reading.
    throwInput(file, "not a readable VTK PolyData file: a data block asks for more memory than there is (corrupt?)");
  } catch (const std::length_error&) {
    throwInput(file, "not a readable VTK PolyData file: a data block has an impossible size (corrupt?)");
  }
  vtkPolyData* poly = reader->GetOutput();
  failIfErrors();
  if (!poly) throwInput(file, "not a readable VTK PolyData file (truncated or corrupt?)");

  const std::string kind = fieldString(poly->GetFieldData(), kindKey);
  if (!kind.empty() && kind != toString(set.kind()))
    throwInput(file, "holds a '" + kind + "' particle set, expected '" + toString(set.kind()) + "'");

  const vtkIdType n = poly->GetNumberOfPoints();
  vtkDataArray* coordinates = poly->GetPoints() ? poly->GetPoints()->GetData() : nullptr;
  if (n > 0 && (!coordinates || !isFloating(coordinates->GetDataType()) || coordinates->GetNumberOfComponents() != 3))
    throw InputError(where("") + "points are not 3-component floating-point coordinates");
  if (n > 0) {
    const auto* xInfo = set.info(field::x);
    if (xInfo && (xInfo->role & Restart) == Restart) {
      if (const vtkIdType bad = firstNonFinite(coordinates); bad >= 0)
        throw InputError(where("") + "point coordinates: particle " + std::to_string(bad) +
                         " has a NaN or infinite value");
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
    const std::string prefix = where(name);
    auto* array = vtkDataArray::SafeDownCast(abstract);
    if (!array) throw InputError(prefix + quoted + " is not numeric (" + abstract->GetClassName() + ")");
    if (name == field::x)
      throw InputError(prefix + quoted + " clashes with the point coordinates, which are field 'x'");
    if (array->GetNumberOfTuples() != n)
      throw InputError(prefix + quoted + " has " + std::to_string(array->GetNumberOfTuples()) + " values, expected " +
                       std::to_string(n) + " (one per point)");

    const int components = array->GetNumberOfComponents();
    const int dataType = array->GetDataType();
    FieldType type;
    if (isIntegral(dataType) && components == 1) type = FieldType::Int;
    else if (isFloating(dataType) && components == 1) type = FieldType::Real;
    else if (isFloating(dataType) && components == 3) type = FieldType::Vec3;
    else if (isFloating(dataType) && components == 9) type = FieldType::Mat3;
    else
      throw InputError(prefix + quoted + " has " + std::to_string(components) + " component(s) of type " +
                       array->GetDataTypeAsString() + "; expected 1 integer or 1, 3 or 9 floating-point components");

    const auto* existing = set.info(name);
    if (existing && existing->type != type)
      throw InputError(prefix + quoted + " holds " + typeName(type) + " values, but field '" + name + "' of set '" +
                       set.name() + "' is " + typeName(existing->type));
    if (type == FieldType::Int) {
      if (const vtkIdType bad = firstOutOfInt64(array); bad >= 0)
        throw InputError(prefix + quoted + ": particle " + std::to_string(bad) + " has a value beyond the Int64 range");
    } else if (existing && (existing->role & Restart) == Restart) {
      // A restart field feeds the next step directly; NaN would only surface as a diverged solve.
      if (const vtkIdType bad = firstNonFinite(array); bad >= 0)
        throw InputError(prefix + quoted + ": particle " + std::to_string(bad) +
                         " has a NaN or infinite value in a restart field");
    }
    transfers.push_back({array, name, type});
  }

  // Resize through zero so fields absent from the file read as zero rather than stale values.
  set.resize(0);
  set.resize(static_cast<std::size_t>(n));
  if (n > 0) copyToDoubles(coordinates, set.x().front().data());
  std::vector<std::string> names;
  for (const auto& t : transfers) {
    copyTo(set, t);
    names.push_back(t.name);
  }
  return names;
}

} // namespace poro
