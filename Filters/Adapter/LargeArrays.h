/**
 * @file LargeArrays.h
 * @brief VTK arrays of the output whose memory comes from Core/util/Buffer.h's AllocateFreeable:
 * on huge pages when large, so that writing them faults their pages in 2 MiB at a time.
 */
#ifndef colordecimation_LargeArrays_h
#define colordecimation_LargeArrays_h

#include "Core/util/Buffer.h"

#include "vtkAbstractArray.h"
#include "vtkIdList.h"
#include "vtkType.h"

#include <cstddef>
#include <cstdlib>
#include <new>

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
 * large, freed by the array with FreeLarge; returns them, or null (the array untouched) when
 * there are none. Without memory for them, throws std::bad_alloc rather than leave the
 * allocation to VTK: a VTK built without NDEBUG (ParaView 5.11's) calls abort() when one of
 * its arrays cannot allocate (vtkGenericDataArray::Allocate, Resize).
 */
inline void* AdoptFreeable(vtkAbstractArray* array, vtkIdType values, size_t valueBytes)
{
  if (values <= 0)
  {
    return nullptr;
  }
  const size_t bytes = static_cast<size_t>(values) * valueBytes;
  void* memory = AllocateFreeable(bytes);
  memory = memory ? memory : std::malloc(bytes); // huge pages' alignment may be what failed
  if (!memory)
  {
    throw std::bad_alloc();
  }
  array->SetVoidArray(memory, values, 0, vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(FreeLarge);
  return memory;
}

/// Throws std::bad_alloc when `array` holds fewer than `values` values: VTK reports a failed
/// allocation (SetNumberOfValues, SetNumberOfTuples) with an error and an empty array, and the
/// filter ends its run on that exception instead of writing through a null pointer.
inline void RequireValues(vtkAbstractArray* array, vtkIdType values)
{
  if (array->GetNumberOfValues() < values)
  {
    throw std::bad_alloc();
  }
}

/// Throws std::bad_alloc when `ids` (just sized to `count`) holds no memory for them.
inline void RequireIds(vtkIdList* ids, vtkIdType count)
{
  if (count > 0 && (ids->GetNumberOfIds() < count || !ids->GetPointer(0)))
  {
    throw std::bad_alloc();
  }
}

/// `values` unwritten values for `array` (a vtkAOSDataArrayTemplate), on huge pages when large;
/// std::bad_alloc when there is no memory for them.
template <typename Array>
void AllocateValues(Array* array, vtkIdType values)
{
  if (!AdoptFreeable(array, values, sizeof(typename Array::ValueType)))
  {
    array->SetNumberOfValues(0); // none asked for
  }
}

} // namespace adapter
} // namespace colordecimation

#endif
