/**
 * @file LargeArrays.h
 * @brief VTK arrays of the output whose memory comes from Core/util/Buffer.h's AllocateFreeable:
 * on huge pages when large, so that writing them faults their pages in 2 MiB at a time.
 */
#ifndef colordecimation_LargeArrays_h
#define colordecimation_LargeArrays_h

#include "Core/util/Buffer.h"

#include "vtkType.h"

#include <cstddef>

namespace colordecimation
{
namespace adapter
{

/// `values` unwritten values for `array` (a vtkAOSDataArrayTemplate), on huge pages when large.
template <typename Array>
void AllocateValues(Array* array, vtkIdType values)
{
  using Value = typename Array::ValueType;
  void* memory =
    values > 0 ? AllocateFreeable(static_cast<size_t>(values) * sizeof(Value)) : nullptr;
  if (!memory)
  {
    array->SetNumberOfValues(values);
    return;
  }
  array->SetArray(static_cast<Value*>(memory), values, 0, Array::VTK_DATA_ARRAY_FREE);
}

} // namespace adapter
} // namespace colordecimation

#endif
