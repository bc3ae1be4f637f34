#include "schedule/PieceQueue.h"

#include "mesh/HalfEdgeMesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace colordecimation
{

void PieceQueue::Reset(Pieces pieces, std::vector<double> costs, std::vector<double> squaredErrors)
{
  this->P = std::move(pieces);
  this->Costs = std::move(costs);
  this->SquaredErrors = std::move(squaredErrors);
  this->Order.clear();
  for (int32_t p = 0; p < static_cast<int32_t>(this->Costs.size()); ++p)
  {
    if (!std::isnan(this->Costs[p]))
    {
      this->Order.push_back(p);
    }
  }
  const std::vector<double>& cost = this->Costs;
  std::sort(this->Order.begin(), this->Order.end(),
            [&cost](int32_t a, int32_t b)
            { return cost[a] < cost[b] || (cost[a] == cost[b] && a < b); });
  this->Next = 0;
}

void PieceQueue::Pop(const HalfEdgeMesh& mesh, std::vector<int32_t>& faces,
                     std::vector<int32_t>& vertices)
{
  const int32_t p = this->Order[this->Next++];
  faces.clear();
  for (int32_t i = this->P.Start[p]; i < this->P.Start[p + 1]; ++i)
  {
    if (mesh.IsFaceAlive(this->P.Faces[i]))
    {
      faces.push_back(this->P.Faces[i]);
    }
  }
  PieceVertices(mesh, faces.data(), faces.size(), vertices);
}

size_t PieceQueue::Bytes() const
{
  return sizeof(int32_t) * (this->P.Start.size() + this->P.Faces.size() + this->Order.size()) +
    sizeof(double) * (this->Costs.size() + this->SquaredErrors.size());
}

} // namespace colordecimation
