/**
 * @file LargeArrays.h
 * @brief VTK arrays of the output whose memory comes from Core/util/Buffer.h's AllocateFreeable:
 * on huge pages when large, so that writing them faults their pages in 2 MiB at a time.
 */
#ifndef colordecimation_LargeArrays_h
#define colordecimation_LargeArrays_h

#include "Core/util/Buffer.h"

#include "vtkAbstractArray.h"
#include "vtkType.h"

#include <cstddef>
#include <cstdlib>

namespace colordecimation
{
namespace adapter
{

/// Frees what AllocateFreeable returned, with this module's own runtime (handed to a VTK array
/// as its free function: VTK's own `free` may belong to another runtime on Windows).
inline void FreeLarge(void* memory)
{
  std::free(memory);
}

/// Whether `array` keeps its values in one contiguous block that SetVoidArray can take.
inline bool IsContiguous(vtkAbstractArray* array)
{
  return array->GetArrayType() == vtkAbstractArray::AoSDataArrayTemplate;
}

/**
 * `values` unwritten values of `valueBytes` each for the contiguous `array`, on huge pages when
 * large, freed by the array with FreeLarge; returns them, or null (nothing allocated, the array
 * untouched) when there are none or no memory.
 */
inline void* AdoptFreeable(vtkAbstractArray* array, vtkIdType values, size_t valueBytes)
{
  void* memory = values > 0 ? AllocateFreeable(static_cast<size_t>(values) * valueBytes) : nullptr;
  if (memory)
  {
    array->SetVoidArray(memory, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
    array->SetArrayFreeFunction(FreeLarge);
  }
  return memory;
}

/// `values` unwritten values for `array` (a vtkAOSDataArrayTemplate), on huge pages when large.
template <typename Array>
void AllocateValues(Array* array, vtkIdType values)
{
  if (!AdoptFreeable(array, values, sizeof(typename Array::ValueType)))
  {
    array->SetNumberOfValues(values);
  }
}

} // namespace adapter
} // namespace colordecimation

#endif
