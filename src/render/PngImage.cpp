#include "render/PngImage.hpp"

#include "core/Error.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

namespace poro {

PngImage PngImage::read(const std::filesystem::path& file) {
  vtkNew<vtkPNGReader> reader;
  if (!std::filesystem::exists(file) || !reader->CanReadFile(file.c_str()))
    throw InputError(file.string() + ": not a readable PNG file");
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  const int components = image->GetNumberOfScalarComponents();
  if (image->GetScalarType() != VTK_UNSIGNED_CHAR || components < 3)
    throw InputError(file.string() + ": expected an 8-bit RGB PNG");
  PngImage out;
  out.width = dims[0];
  out.height = dims[1];
  out.rgb.resize(static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]));
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      // VTK's rows start at the bottom.
      const auto* p = static_cast<const std::uint8_t*>(image->GetScalarPointer(x, dims[1] - 1 - y, 0));
      out.rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(dims[0]) + static_cast<std::size_t>(x)] = {p[0], p[1], p[2]};
    }
  return out;
}

} // namespace poro
