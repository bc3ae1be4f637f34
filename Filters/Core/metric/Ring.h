/**
 * @file Ring.h
 * @brief The 1-ring of a vertex as the cost terms read it, in coordinate arrays so that
 * their all-pairs loops vectorise.
 */
#ifndef colordecimation_Ring_h
#define colordecimation_Ring_h

#include <cmath>
#include <cstdint>
#include <vector>

/// Hot all-pairs loops get an AVX2 clone next to the baseline one, picked at load time. Not
/// under ThreadSanitizer: its instrumented load-time resolver would run before the runtime.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__) &&       \
  !defined(__SANITIZE_THREAD__)
#define COLORDECIMATION_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define COLORDECIMATION_VECTOR_CLONES
#endif

namespace colordecimation
{

inline double Distance3(const double* a, const double* b)
{
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
}

inline double SquaredDistance3(const double* a, const double* b)
{
  const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return d0 * d0 + d1 * d1 + d2 * d2;
}

/**
 * The 1-ring of v0 as the cost needs it: neighbour ids, positions and colours (as separate
 * coordinate arrays, so that the all-pairs loops of the cost vectorise), and which neighbours
 * are admissible collapse targets. Reused between calls (no allocation once grown).
 */
struct Ring
{
  int Size = 0;
  std::vector<int32_t> Vertex;
  std::vector<double> X, Y, Z; ///< positions
  std::vector<double> R, G, B; ///< colours
  std::vector<double> QC;      ///< Q(i) at its own position (the quadric's constant term)
  std::vector<uint8_t> IsCandidate;
  std::vector<double> Product; ///< scratch: |c0-ci| |p0-pi|

  /// Size rounded up to a multiple of 4: the arrays hold zeros up to there after Pad().
  int PaddedSize() const { return (this->Size + 3) & ~3; }

  void Clear() { this->Size = 0; }
  void Add(int32_t v, const double p[3], const double c[3], bool candidate, double qc = 0.0)
  {
    if (static_cast<size_t>(this->Size + 4) >= this->Vertex.size())
    {
      this->Grow();
    }
    const int k = this->Size++;
    this->Vertex[k] = v;
    this->X[k] = p[0];
    this->Y[k] = p[1];
    this->Z[k] = p[2];
    this->R[k] = c[0];
    this->G[k] = c[1];
    this->B[k] = c[2];
    this->QC[k] = qc;
    this->IsCandidate[k] = candidate ? 1 : 0;
  }
  /// Zero the entries between Size and PaddedSize (so whole vector lanes can be computed).
  void Pad()
  {
    for (int k = this->Size; k < this->PaddedSize(); ++k)
    {
      this->X[k] = this->Y[k] = this->Z[k] = this->R[k] = this->G[k] = this->B[k] = 0.0;
      this->QC[k] = this->Product[k] = 0.0;
      this->IsCandidate[k] = 0;
    }
  }
  void GetPosition(int k, double p[3]) const
  {
    p[0] = this->X[k];
    p[1] = this->Y[k];
    p[2] = this->Z[k];
  }
  void GetColor(int k, double c[3]) const
  {
    c[0] = this->R[k];
    c[1] = this->G[k];
    c[2] = this->B[k];
  }

private:
  void Grow()
  {
    const size_t n = 2 * this->Vertex.size() + 16; // a multiple of 4
    this->Vertex.resize(n);
    for (auto* v :
         { &this->X, &this->Y, &this->Z, &this->R, &this->G, &this->B, &this->QC, &this->Product })
    {
      v->resize(n);
    }
    this->IsCandidate.resize(n);
  }
};

} // namespace colordecimation

#endif
