#include "lod/CollapseRecord.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace colordecimation
{

void CollapseRecord::Clear()
{
  *this = CollapseRecord();
}

void CollapseRecord::Append(const RecordedCollapse* made, size_t madeCount, const int32_t* toInput,
                            double scale)
{
  const size_t start = this->Size(), count = start + madeCount;
  this->Removed.resize(count);
  this->Survivor.resize(count);
  this->Cost.resize(count);
  this->Error.resize(count);
  this->Triangles.resize(count);
  int64_t left = start > 0 ? this->Triangles[start - 1] : this->InputTriangles;
  for (size_t i = 0; i < madeCount; ++i)
  {
    const RecordedCollapse& c = made[i];
    left -= c.RemovedFaces;
    this->Removed[start + i] = toInput ? toInput[c.V0] : c.V0;
    this->Survivor[start + i] = toInput && c.V1 >= 0 ? toInput[c.V1] : c.V1;
    this->Cost[start + i] = c.Cost;
    this->Error[start + i] = std::sqrt(c.SquaredError) / scale;
    this->Triangles[start + i] = left;
  }
  // A step of several entries (a seam pair, a removed piece) shows the count after it all and
  // its largest error in each: backwards, each entry followed by one continuing its step takes
  // that one's count and the larger error; forwards, each continuing entry the error before.
  const size_t first = start > 0 ? start - 1 : 0;
  for (size_t i = count; i-- > first + 1;)
  {
    if (made[i - start].SecondOfPair)
    {
      this->Triangles[i - 1] = this->Triangles[i];
      this->Error[i - 1] = std::max(this->Error[i - 1], this->Error[i]);
    }
  }
  for (size_t i = std::max(start, size_t(1)); i < count; ++i)
  {
    if (made[i - start].SecondOfPair)
    {
      this->Error[i] = this->Error[i - 1];
    }
  }
}

bool IsSkippedPiece(const CollapseRecord& record, size_t i, double maximumError)
{
  return maximumError > 0 && record.Survivor[i] < 0 && record.Error[i] > maximumError;
}

size_t LevelLength(const CollapseRecord& record, int64_t targetTriangles, double maximumError)
{
  int64_t left = record.InputTriangles; // the record's count before row i
  int64_t kept = 0;                     // the faces of the pieces the level skips
  size_t i = 0;
  for (; i < record.Size(); ++i)
  {
    const bool second = i > 0 && record.Triangles[i] == record.Triangles[i - 1];
    const bool skipped = IsSkippedPiece(record, i, maximumError);
    if (!second &&
        (left + kept <= targetTriangles ||
         (!skipped && maximumError > 0 && record.Error[i] > maximumError)))
    {
      break;
    }
    kept += skipped && !second ? left - record.Triangles[i] : 0;
    left = record.Triangles[i];
  }
  return i;
}

bool IsConsistent(const CollapseRecord& record, std::string& why)
{
  const size_t n = record.Size();
  if (record.Survivor.size() != n || record.Cost.size() != n || record.Error.size() != n ||
      record.Triangles.size() != n || record.InputPoints < 0 || record.InputTriangles < 0)
  {
    why = "its columns differ in length, or its mesh sizes are negative";
    return false;
  }
  std::vector<uint8_t> removed(static_cast<size_t>(record.InputPoints), 0);
  int64_t left = record.InputTriangles;
  bool paired = false; // the last collapse was the second of a pair
  for (size_t i = 0; i < n; ++i)
  {
    // Survivor -1: the vertex went with its piece, removed whole (section 14).
    const int32_t v0 = record.Removed[i], v1 = record.Survivor[i];
    if (v0 < 0 || v1 < -1 || v0 >= record.InputPoints || v1 >= record.InputPoints || v0 == v1)
    {
      why = "collapse " + std::to_string(i) + " names a point id out of range [0, " +
        std::to_string(record.InputPoints) + ") or the same point twice";
      return false;
    }
    if (removed[v0] || (v1 >= 0 && removed[v1]))
    {
      why = "collapse " + std::to_string(i) + " names a point that an earlier one removed";
      return false;
    }
    removed[v0] = 1;
    // Equal counts: the second collapse of a pair (not a third), or a further vertex of a
    // removed piece.
    const bool piece = v1 < 0 && i > 0 && record.Survivor[i - 1] < 0;
    const bool second = i > 0 && record.Triangles[i] == left &&
      (piece || (!paired && v1 >= 0 && record.Survivor[i - 1] >= 0));
    paired = second && !piece;
    if ((record.Triangles[i] >= left && !second) || record.Triangles[i] < 0)
    {
      why = "its triangle counts do not decrease from the input's " +
        std::to_string(record.InputTriangles) + " (collapse " + std::to_string(i) + ")";
      return false;
    }
    left = record.Triangles[i];
  }
  return true;
}

void ResolveSurvivors(const CollapseRecord& record, size_t count, std::vector<int32_t>& where,
                      double maximumError)
{
  where.resize(static_cast<size_t>(record.InputPoints));
  std::iota(where.begin(), where.end(), 0);
  for (size_t i = 0; i < count && i < record.Size(); ++i)
  {
    if (!IsSkippedPiece(record, i, maximumError))
    {
      where[record.Removed[i]] = record.Survivor[i];
    }
  }
  // Each chain of parents ends at a survivor, or at -1 (a removed piece); every vertex on it
  // is pointed there at once.
  for (size_t v = 0; v < where.size(); ++v)
  {
    int32_t root = where[v];
    while (root >= 0 && where[root] != root)
    {
      root = where[root];
    }
    for (int32_t u = static_cast<int32_t>(v); u >= 0 && where[u] != root;)
    {
      const int32_t next = where[u];
      where[u] = root;
      u = next;
    }
  }
}

} // namespace colordecimation
