/**
 * @file Seams.h
 * @brief Attribute seams: vertices at exactly the same position with their own point data
 * (docs/ALGORITHM.md, section 15).
 *
 * Exporters split a vertex where its colour, texture coordinates or normal jump (a UV sphere's
 * meridian, the edges of a cube whose faces have their own colour). Each side is then an open
 * boundary of its own. A *seam edge* is a boundary edge whose two end points have, bit for bit,
 * the positions of another boundary edge's end points. A boundary vertex on a seam edge is a
 * seam vertex:
 * - *twinned*: exactly one other boundary vertex has its position (its twin, on the other
 *   side); it collapses only along a seam edge whose mirror edge exists, together with the
 *   mirror collapse (the pair, see Admits and AreApart);
 * - *shared*: no other vertex has its position (both sides use it, e.g. a pole where a
 *   meridian seam ends); it never collapses into a seam vertex;
 * - with more than one twin (a cube corner where three faces meet): locked.
 * Positions never change in a half-edge collapse, so the roles found at set-up hold to the end.
 */
#ifndef colordecimation_Seams_h
#define colordecimation_Seams_h

#include "vtkColorDecimationModule.h" // for export macro

#include <cstddef>
#include <cstdint>
#include <vector>

namespace colordecimation
{
class HalfEdgeMesh;

/// What the detection found.
struct SeamReport
{
  int64_t TwinnedVertices = 0;
  int64_t SharedVertices = 0;
  int64_t LockedVertices = 0; ///< seam vertices with more than one twin (or all, lockAll)
};

class VTKCOLORDECIMATION_EXPORT SeamMap
{
public:
  enum Role : uint8_t
  {
    None = 0,
    Twinned = 1,
    Shared = 2
  };

  /**
   * Find the seams among the unlocked boundary vertices of `mesh`; vertex v is at
   * points[3 * source[v]] (source null: at points[3 * v]). Locks the seam vertices with more
   * than one twin, and every seam vertex when lockAll (collapses that move vertices could not
   * keep the two sides together). Leaves the map empty when there is no seam.
   */
  SeamReport Detect(HalfEdgeMesh& mesh, const double* points, const int32_t* source, bool lockAll,
                    int threads);

  bool Empty() const { return this->Roles.empty(); }
  Role GetRole(int32_t v) const
  {
    return this->Roles.empty() ? None : static_cast<Role>(this->Roles[v]);
  }
  /// The twin of a twinned vertex, -1 for any other.
  int32_t GetTwin(int32_t v) const { return this->GetRole(v) == Twinned ? this->Twins[v] : -1; }
  /// Where the mirror of a collapse into seam vertex v1 goes: its twin, or v1 itself when both
  /// sides share it; -1 when v1 is no seam vertex.
  int32_t MirrorTarget(int32_t v1) const
  {
    const Role role = this->GetRole(v1);
    return role == Twinned ? this->Twins[v1] : (role == Shared ? v1 : -1);
  }

  /**
   * Whether seam vertex v0 may collapse into v1, its neighbour along a boundary edge: a twinned
   * v0 along a seam edge whose mirror edge twin(v0)-MirrorTarget(v1) is a boundary edge, a
   * shared v0 only into a vertex that is no seam vertex.
   */
  bool Admits(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1) const;

  /**
   * Whether the collapses v0 -> v1 and t0 -> m1 of a pair leave each other's rules unchanged:
   * the closed 1-rings of v0 and t0 share no vertex but v1 when m1 == v1. Then either one
   * reads no face, twin or valence the other writes, so both may be checked before either is
   * made. `scratch` is reused.
   */
  static bool AreApart(const HalfEdgeMesh& mesh, int32_t v0, int32_t v1, int32_t t0, int32_t m1,
                       std::vector<int32_t>& scratch);

  void Release();
  size_t Bytes() const { return this->Roles.size() + 4 * this->Twins.size(); }

private:
  std::vector<uint8_t> Roles; ///< per vertex, empty without seams
  std::vector<int32_t> Twins; ///< per vertex, the twin of a twinned one
};

} // namespace colordecimation

#endif
