// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLRSplineElementLocator.h"
#include "vtkSplineVizError.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

using vtkSplineVizError::Fail;

namespace
{
using Word = std::uint32_t;

// The first word of a list leaf (overlapping boxes): direction bits 3.
inline bool IsListWord(Word w)
{
  return (w & vtkLRSplineElementLocator::LeafBit) == 0 && ((w >> 29) & 3u) == 3u;
}

// A depth-balanced k-d tree over a set of element boxes, written into flat
// arrays with LOCAL child indices (the caller adds the global offset).
struct SubtreeBuilder
{
  const double* Boxes;
  // Boxes may overlap (bounding boxes of curved elements): a set that no
  // split separates becomes a list leaf instead of keeping its first element.
  bool Overlap = false;
  std::vector<Word> Words;
  std::vector<double> Splits;
  // scratch
  std::vector<double> Lo, Hi, Candidates;
  // left/right element lists per depth (a deque: growing it keeps references valid)
  std::deque<std::vector<vtkIdType>> Pool;

  // Split choice (Fuchs §3.2.1): for each direction, every element boundary
  // strictly inside the region is a candidate; count the elements left
  // (lo < s) and right (hi > s) of it; take the one with the smallest larger
  // side, then the fewest duplicated elements. A split that leaves all
  // elements on one side is used only when no other exists (invalid meshes).
  bool ChooseSplit(
    const std::vector<vtkIdType>& elems, const double region[6], int& dir, double& split)
  {
    const std::size_t n = elems.size();
    bool found = false;
    int bestWeak = 2;
    std::size_t bestMax = 0, bestSum = 0;
    auto consider = [&](int d, double s, std::size_t left, std::size_t right)
    {
      const int weak = (left < n && right < n) ? 0 : 1;
      const std::size_t mx = std::max(left, right);
      const std::size_t sum = left + right;
      if (!found || weak < bestWeak ||
        (weak == bestWeak && (mx < bestMax || (mx == bestMax && sum < bestSum))))
      {
        found = true;
        bestWeak = weak;
        bestMax = mx;
        bestSum = sum;
        dir = d;
        split = s;
      }
    };
    if (n <= 16)
    {
      // Few elements: count directly (same choice as the sorted path below,
      // candidates visited in increasing order per direction).
      double cand[32];
      for (int d = 0; d < 3; ++d)
      {
        int nc = 0;
        for (std::size_t k = 0; k < n; ++k)
        {
          const double* b = this->Boxes + 6 * elems[k];
          for (const double v : { b[d], b[d + 3] })
          {
            if (v > region[d] && v < region[d + 3])
            {
              cand[nc++] = v;
            }
          }
        }
        std::sort(cand, cand + nc);
        nc = static_cast<int>(std::unique(cand, cand + nc) - cand);
        for (int c = 0; c < nc; ++c)
        {
          std::size_t left = 0, right = 0;
          for (std::size_t k = 0; k < n; ++k)
          {
            const double* b = this->Boxes + 6 * elems[k];
            left += b[d] < cand[c] ? 1 : 0;
            right += b[d + 3] > cand[c] ? 1 : 0;
          }
          consider(d, cand[c], left, right);
        }
      }
      return found;
    }
    this->Lo.resize(n);
    this->Hi.resize(n);
    for (int d = 0; d < 3; ++d)
    {
      this->Candidates.clear();
      for (std::size_t k = 0; k < n; ++k)
      {
        const double* b = this->Boxes + 6 * elems[k];
        this->Lo[k] = b[d];
        this->Hi[k] = b[d + 3];
        if (b[d] > region[d] && b[d] < region[d + 3])
        {
          this->Candidates.push_back(b[d]);
        }
        if (b[d + 3] > region[d] && b[d + 3] < region[d + 3])
        {
          this->Candidates.push_back(b[d + 3]);
        }
      }
      if (this->Candidates.empty())
      {
        continue;
      }
      std::sort(this->Lo.begin(), this->Lo.end());
      std::sort(this->Hi.begin(), this->Hi.end());
      std::sort(this->Candidates.begin(), this->Candidates.end());
      this->Candidates.erase(
        std::unique(this->Candidates.begin(), this->Candidates.end()), this->Candidates.end());
      for (double s : this->Candidates)
      {
        const std::size_t left = static_cast<std::size_t>(
          std::lower_bound(this->Lo.begin(), this->Lo.end(), s) - this->Lo.begin());
        const std::size_t right = static_cast<std::size_t>(
          this->Hi.end() - std::upper_bound(this->Hi.begin(), this->Hi.end(), s));
        consider(d, s, left, right);
      }
    }
    return found;
  }

  // True when both sides of the split (d, s) have fewer elements than the set.
  bool Separates(const std::vector<vtkIdType>& elems, int d, double s) const
  {
    std::size_t left = 0, right = 0;
    for (vtkIdType e : elems)
    {
      const double* b = this->Boxes + 6 * e;
      left += b[d] < s ? 1 : 0;
      right += b[d + 3] > s ? 1 : 0;
    }
    return left < elems.size() && right < elems.size();
  }

  // Returns the depth of the subtree (0 for a leaf).
  int Build(const std::vector<vtkIdType>& elems, const double region[6], std::size_t depth = 0)
  {
    if (elems.size() <= 1)
    {
      this->Words.push_back(elems.empty()
          ? vtkLRSplineElementLocator::NoElement
          : (vtkLRSplineElementLocator::LeafBit | static_cast<Word>(elems[0])));
      this->Splits.push_back(0.0);
      return 0;
    }
    int d = 0;
    double s = 0.0;
    const bool split = this->ChooseSplit(elems, region, d, s);
    if (this->Overlap && (!split || !this->Separates(elems, d, s)))
    {
      // A list leaf: the word (3 << 29) | count, then one leaf word per element.
      this->Words.push_back((Word(3) << 29) | static_cast<Word>(elems.size()));
      this->Splits.push_back(0.0);
      for (vtkIdType e : elems)
      {
        this->Words.push_back(vtkLRSplineElementLocator::LeafBit | static_cast<Word>(e));
        this->Splits.push_back(0.0);
      }
      return 0;
    }
    if (!split)
    {
      // Every element covers the whole region: overlapping elements (invalid
      // input, rejected elsewhere). Keep the first.
      this->Words.push_back(vtkLRSplineElementLocator::LeafBit | static_cast<Word>(elems[0]));
      this->Splits.push_back(0.0);
      return 0;
    }
    if (this->Pool.size() < 2 * depth + 2)
    {
      this->Pool.resize(2 * depth + 2);
    }
    // (the right subtree uses deeper buffers only, so `left` survives it)
    std::vector<vtkIdType>& left = this->Pool[2 * depth];
    std::vector<vtkIdType>& right = this->Pool[2 * depth + 1];
    left.clear();
    right.clear();
    for (vtkIdType e : elems)
    {
      const double* b = this->Boxes + 6 * e;
      if (b[d] < s)
      {
        left.push_back(e);
      }
      if (b[d + 3] > s)
      {
        right.push_back(e);
      }
    }
    const std::size_t index = this->Words.size();
    this->Words.push_back(static_cast<Word>(d) << 29);
    this->Splits.push_back(s);
    double rr[6], lr[6];
    std::copy(region, region + 6, rr);
    std::copy(region, region + 6, lr);
    rr[d] = s;
    lr[d + 3] = s;
    const int dr = this->Build(this->Pool[2 * depth + 1], rr, depth + 1); // right child: index + 1
    this->Words[index] |= static_cast<Word>(this->Words.size());
    const int dl = this->Build(this->Pool[2 * depth], lr, depth + 1);
    return 1 + std::max(dl, dr);
  }
};

void Accumulate(std::vector<int>& depths, vtkLRSplineElementLocator::Statistics& st)
{
  if (depths.empty())
  {
    return;
  }
  st.MinDepth = *std::min_element(depths.begin(), depths.end());
  st.MaxDepth = *std::max_element(depths.begin(), depths.end());
  double sum = 0.0, sum2 = 0.0;
  for (int d : depths)
  {
    sum += d;
    sum2 += static_cast<double>(d) * d;
  }
  const double n = static_cast<double>(depths.size());
  st.MeanDepth = sum / n;
  st.VarianceDepth = std::max(0.0, sum2 / n - st.MeanDepth * st.MeanDepth);
}
}

//------------------------------------------------------------------------------
const char* vtkLRSplineElementLocator::GetTypeName(int type)
{
  switch (type)
  {
    case LINEAR:
      return "linear search";
    case KD_TREE:
      return "k-d tree";
    case KD_FOREST:
      return "k-d forest";
    case OCTREE:
      return "octree";
    case TEXTURE:
      return "lookup texture";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineElementLocator::ComputeDyadicLevels(
  const double* boxes, vtkIdType n, const double domain[6], int levels[3])
{
  levels[0] = levels[1] = levels[2] = 0;
  for (vtkIdType e = 0; e < n; ++e)
  {
    for (int c = 0; c < 6; ++c)
    {
      const int d = c % 3;
      const double t = (boxes[6 * e + c] - domain[d]) / (domain[d + 3] - domain[d]);
      int level = -1;
      for (int l = 0; l <= 30; ++l)
      {
        const double v = std::ldexp(t, l);
        if (v == std::floor(v))
        {
          level = l;
          break;
        }
      }
      if (level < 0)
      {
        return false;
      }
      levels[d] = std::max(levels[d], level);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
std::vector<float> vtkLRSplineElementLocator::GetNodeSplitsFloat() const
{
  return std::vector<float>(this->NodeSplits.begin(), this->NodeSplits.end());
}

//------------------------------------------------------------------------------
bool vtkLRSplineElementLocator::Build(
  const double* boxes, vtkIdType n, int type, const int blocks[3], std::string* error)
{
  this->Boxes.assign(boxes, boxes + 6 * n);
  this->Heads.clear();
  this->NodeWords.clear();
  this->NodeSplits.clear();
  this->OctreeNodes.clear();
  for (auto& e : this->Edges)
  {
    e.clear();
  }
  this->Stats = Statistics();
  this->Blocks[0] = this->Blocks[1] = this->Blocks[2] = 0;
  this->Type = type;
  if (n < 1)
  {
    return Fail(error, "no elements");
  }
  if (n > static_cast<vtkIdType>(ElementMask) - 1)
  {
    return Fail(error, "too many elements for the locator");
  }
  for (int d = 0; d < 3; ++d)
  {
    this->Domain[d] = std::numeric_limits<double>::infinity();
    this->Domain[d + 3] = -std::numeric_limits<double>::infinity();
  }
  for (vtkIdType e = 0; e < n; ++e)
  {
    const double* b = boxes + 6 * e;
    for (int d = 0; d < 3; ++d)
    {
      if (!(b[d] < b[d + 3]) || !std::isfinite(b[d]) || !std::isfinite(b[d + 3]))
      {
        return Fail(error, "element " + std::to_string(e) + " has an empty or invalid box");
      }
      this->Domain[d] = std::min(this->Domain[d], b[d]);
      this->Domain[d + 3] = std::max(this->Domain[d + 3], b[d + 3]);
    }
  }

  if (this->AllowOverlap && type != LINEAR && type != KD_TREE && type != KD_FOREST)
  {
    return Fail(
      error, "overlapping element boxes need a linear search, a k-d tree or a k-d forest");
  }
  switch (type)
  {
    case LINEAR:
      this->Stats.MemoryBytes = this->Boxes.size() * sizeof(double);
      return true;
    case KD_TREE:
    {
      const int one[3] = { 1, 1, 1 };
      return this->BuildForest(one, error);
    }
    case KD_FOREST:
    {
      const int def[3] = { 8, 8, 8 };
      const int* b = blocks ? blocks : def;
      if (b[0] < 1 || b[1] < 1 || b[2] < 1 ||
        static_cast<double>(b[0]) * b[1] * b[2] > 1024.0 * 1024.0 * 1024.0)
      {
        return Fail(error, "the number of forest blocks must be at least 1 and at most 2^30");
      }
      return this->BuildForest(b, error);
    }
    case TEXTURE:
    {
      int levels[3];
      if (!ComputeDyadicLevels(boxes, n, this->Domain, levels))
      {
        return Fail(error,
          "a lookup texture needs dyadic knots (every element boundary at a multiple "
          "of 2^-l of the domain), and these knots are not");
      }
      int size[3];
      double total = 1.0;
      for (int d = 0; d < 3; ++d)
      {
        if (levels[d] > 11)
        {
          return Fail(error, "the lookup texture would need more than 2048 texels per direction");
        }
        size[d] = 1 << levels[d];
        total *= size[d];
      }
      if (total > 134217728.0)
      {
        return Fail(error, "the lookup texture would need more than 2^27 texels");
      }
      if (!this->BuildForest(size, error))
      {
        return false;
      }
      this->Type = TEXTURE;
      if (this->Stats.NumberOfLeafBlocks != this->Stats.NumberOfBlocks)
      {
        return Fail(error, "the lookup texture has cells with more than one element");
      }
      return true;
    }
    case OCTREE:
      return this->BuildOctree(error);
    default:
      return Fail(error, "unknown locator type " + std::to_string(type));
  }
}

//------------------------------------------------------------------------------
bool vtkLRSplineElementLocator::BuildForest(const int blocks[3], std::string* error)
{
  const vtkIdType n = this->GetNumberOfElements();
  for (int d = 0; d < 3; ++d)
  {
    this->Blocks[d] = blocks[d];
    const double lo = this->Domain[d], hi = this->Domain[d + 3];
    this->Edges[d].resize(blocks[d] + 1);
    for (int i = 0; i <= blocks[d]; ++i)
    {
      this->Edges[d][i] = lo + (hi - lo) * (static_cast<double>(i) / blocks[d]);
    }
    this->Edges[d][0] = lo;
    this->Edges[d][blocks[d]] = hi;
    this->InvBlockWidth[d] = blocks[d] / (hi - lo);
  }
  const vtkIdType I = blocks[0], J = blocks[1], K = blocks[2];
  const vtkIdType IJ = I * J;
  this->Heads.assign(static_cast<std::size_t>(IJ * K), NoElement);

  // Block ranges of every element: blocks b with edge[b] < hi and edge[b+1] > lo.
  std::vector<int> range(6 * static_cast<std::size_t>(n));
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const double* b = this->Boxes.data() + 6 * e;
        for (int d = 0; d < 3; ++d)
        {
          const std::vector<double>& E = this->Edges[d];
          const int nb = this->Blocks[d];
          int i0 =
            static_cast<int>(std::upper_bound(E.begin() + 1, E.end(), b[d]) - (E.begin() + 1));
          int i1 =
            static_cast<int>(std::lower_bound(E.begin(), E.begin() + nb, b[d + 3]) - E.begin()) - 1;
          i0 = std::max(0, std::min(i0, nb - 1));
          i1 = std::max(0, std::min(i1, nb - 1));
          range[6 * e + d] = i0;
          range[6 * e + d + 3] = i1;
        }
      }
    });

  // Elements per k-slab (CSR).
  std::vector<vtkIdType> slabOffsets(K + 1, 0);
  for (vtkIdType e = 0; e < n; ++e)
  {
    for (int k = range[6 * e + 2]; k <= range[6 * e + 5]; ++k)
    {
      ++slabOffsets[k + 1];
    }
  }
  for (vtkIdType k = 0; k < K; ++k)
  {
    slabOffsets[k + 1] += slabOffsets[k];
  }
  std::vector<vtkIdType> slabElems(slabOffsets[K]);
  {
    std::vector<vtkIdType> fill(slabOffsets.begin(), slabOffsets.end() - 1);
    for (vtkIdType e = 0; e < n; ++e)
    {
      for (int k = range[6 * e + 2]; k <= range[6 * e + 5]; ++k)
      {
        slabElems[fill[k]++] = e;
      }
    }
  }

  std::vector<int> depths(static_cast<std::size_t>(IJ * K), 0);
  std::vector<vtkIdType> blockOffsets(IJ + 1);
  std::vector<vtkIdType> blockElems;
  std::vector<std::vector<Word>> words(IJ);
  std::vector<std::vector<double>> splits(IJ);
  bool tooLarge = false;
  for (vtkIdType k = 0; k < K && !tooLarge; ++k)
  {
    // Elements per block of this slab (CSR).
    std::fill(blockOffsets.begin(), blockOffsets.end(), 0);
    for (vtkIdType s = slabOffsets[k]; s < slabOffsets[k + 1]; ++s)
    {
      const vtkIdType e = slabElems[s];
      for (int j = range[6 * e + 1]; j <= range[6 * e + 4]; ++j)
      {
        for (int i = range[6 * e + 0]; i <= range[6 * e + 3]; ++i)
        {
          ++blockOffsets[j * I + i + 1];
        }
      }
    }
    for (vtkIdType b = 0; b < IJ; ++b)
    {
      blockOffsets[b + 1] += blockOffsets[b];
    }
    blockElems.resize(blockOffsets[IJ]);
    {
      std::vector<vtkIdType> fill(blockOffsets.begin(), blockOffsets.end() - 1);
      for (vtkIdType s = slabOffsets[k]; s < slabOffsets[k + 1]; ++s)
      {
        const vtkIdType e = slabElems[s];
        for (int j = range[6 * e + 1]; j <= range[6 * e + 4]; ++j)
        {
          for (int i = range[6 * e + 0]; i <= range[6 * e + 3]; ++i)
          {
            blockElems[fill[j * I + i]++] = e;
          }
        }
      }
    }
    // Trees of the blocks with several elements, in parallel.
    vtkSMPTools::For(0, IJ,
      [&](vtkIdType begin, vtkIdType end)
      {
        SubtreeBuilder builder;
        builder.Boxes = this->Boxes.data();
        builder.Overlap = this->AllowOverlap;
        for (vtkIdType b = begin; b < end; ++b)
        {
          const vtkIdType count = blockOffsets[b + 1] - blockOffsets[b];
          const vtkIdType head = k * IJ + b;
          if (count == 0)
          {
            this->Heads[head] = NoElement;
            continue;
          }
          if (count == 1)
          {
            this->Heads[head] = LeafBit | static_cast<Word>(blockElems[blockOffsets[b]]);
            continue;
          }
          const vtkIdType i = b % I, j = b / I;
          const double region[6] = { this->Edges[0][i], this->Edges[1][j], this->Edges[2][k],
            this->Edges[0][i + 1], this->Edges[1][j + 1], this->Edges[2][k + 1] };
          std::vector<vtkIdType> elems(
            blockElems.begin() + blockOffsets[b], blockElems.begin() + blockOffsets[b + 1]);
          builder.Words.clear();
          builder.Splits.clear();
          depths[head] = builder.Build(elems, region);
          words[b] = builder.Words;
          splits[b] = builder.Splits;
        }
      });
    // Concatenate in block order with global child indices.
    for (vtkIdType b = 0; b < IJ; ++b)
    {
      if (words[b].empty())
      {
        continue;
      }
      const std::size_t base = this->NodeWords.size();
      if (base + words[b].size() > ChildMask)
      {
        tooLarge = true;
        break;
      }
      for (Word w : words[b])
      {
        if (!(w & LeafBit) && !IsListWord(w))
        {
          w = (w & ~ChildMask) | static_cast<Word>((w & ChildMask) + base);
        }
        this->NodeWords.push_back(w);
      }
      this->NodeSplits.insert(this->NodeSplits.end(), splits[b].begin(), splits[b].end());
      this->Heads[k * IJ + b] = static_cast<Word>(base);
      std::vector<Word>().swap(words[b]);
      std::vector<double>().swap(splits[b]);
    }
  }
  if (tooLarge)
  {
    return error ? (*error = "the k-d forest needs more than 2^29 nodes", false) : false;
  }
  this->Stats.NumberOfBlocks = IJ * K;
  this->Stats.NumberOfNodes = static_cast<vtkIdType>(this->NodeWords.size());
  vtkIdType leaves = 0;
  for (Word h : this->Heads)
  {
    leaves += (h & LeafBit) ? 1 : 0;
  }
  this->Stats.NumberOfLeafBlocks = leaves;
  Accumulate(depths, this->Stats);
  this->Stats.MemoryBytes = this->Heads.size() * sizeof(Word) +
    this->NodeWords.size() * sizeof(Word) + this->NodeSplits.size() * sizeof(double) +
    (this->Edges[0].size() + this->Edges[1].size() + this->Edges[2].size()) * sizeof(double) +
    this->Boxes.size() * sizeof(double);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLRSplineElementLocator::BuildOctree(std::string* error)
{
  const vtkIdType n = this->GetNumberOfElements();
  int levels[3];
  if (!ComputeDyadicLevels(this->Boxes.data(), n, this->Domain, levels))
  {
    return Fail(error,
      "an octree needs dyadic knots (every element boundary at a multiple of 2^-l "
      "of the domain), and these knots are not");
  }
  const int maxLevel = std::max(levels[0], std::max(levels[1], levels[2]));
  const std::size_t maxNodes = std::size_t(1) << 28;
  std::vector<int> leafDepths;

  struct Task
  {
    Word Node;
    double Region[6];
    std::vector<vtkIdType> Elems;
    int Level;
  };
  this->OctreeNodes.assign(1, NoElement);
  std::vector<Task> stack;
  {
    Task root;
    root.Node = 0;
    std::copy(this->Domain, this->Domain + 6, root.Region);
    root.Elems.resize(n);
    for (vtkIdType e = 0; e < n; ++e)
    {
      root.Elems[e] = e;
    }
    root.Level = 0;
    stack.push_back(std::move(root));
  }
  while (!stack.empty())
  {
    Task task = std::move(stack.back());
    stack.pop_back();
    if (task.Elems.size() <= 1)
    {
      this->OctreeNodes[task.Node] =
        task.Elems.empty() ? NoElement : (LeafBit | static_cast<Word>(task.Elems[0]));
      leafDepths.push_back(task.Level);
      continue;
    }
    if (task.Level >= maxLevel + 1 || this->OctreeNodes.size() + 8 > maxNodes)
    {
      return Fail(error,
        "the octree could not separate the elements (overlapping elements or too many levels)");
    }
    const Word base = static_cast<Word>(this->OctreeNodes.size());
    this->OctreeNodes[task.Node] = base;
    this->OctreeNodes.resize(base + 8, NoElement);
    double mid[3];
    for (int d = 0; d < 3; ++d)
    {
      mid[d] = 0.5 * (task.Region[d] + task.Region[d + 3]);
    }
    for (int c = 7; c >= 0; --c)
    {
      Task child;
      child.Node = base + c;
      child.Level = task.Level + 1;
      for (int d = 0; d < 3; ++d)
      {
        const bool upper = (c >> d) & 1;
        child.Region[d] = upper ? mid[d] : task.Region[d];
        child.Region[d + 3] = upper ? task.Region[d + 3] : mid[d];
      }
      for (vtkIdType e : task.Elems)
      {
        const double* b = this->Boxes.data() + 6 * e;
        bool meets = true;
        for (int d = 0; d < 3; ++d)
        {
          meets = meets && b[d] < child.Region[d + 3] && b[d + 3] > child.Region[d];
        }
        if (meets)
        {
          child.Elems.push_back(e);
        }
      }
      stack.push_back(std::move(child));
    }
  }
  this->Stats.NumberOfNodes = static_cast<vtkIdType>(this->OctreeNodes.size());
  this->Stats.NumberOfBlocks = static_cast<vtkIdType>(leafDepths.size());
  this->Stats.NumberOfLeafBlocks = static_cast<vtkIdType>(leafDepths.size());
  Accumulate(leafDepths, this->Stats);
  this->Stats.MemoryBytes =
    this->OctreeNodes.size() * sizeof(Word) + this->Boxes.size() * sizeof(double);
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineElementLocator::BlockIndex(int d, double x) const
{
  const int nb = this->Blocks[d];
  const std::vector<double>& E = this->Edges[d];
  const double t = (x - this->Domain[d]) * this->InvBlockWidth[d];
  int i = t > 0.0 ? static_cast<int>(std::min(t, static_cast<double>(nb - 1))) : 0;
  while (i > 0 && x < E[i])
  {
    --i;
  }
  while (i < nb - 1 && x >= E[i + 1])
  {
    ++i;
  }
  return i;
}

//------------------------------------------------------------------------------
bool vtkLRSplineElementLocator::Contains(vtkIdType e, const double p[3]) const
{
  const double* b = this->Boxes.data() + 6 * e;
  if (this->AllowOverlap)
  {
    return p[0] >= b[0] && p[0] <= b[3] && p[1] >= b[1] && p[1] <= b[4] && p[2] >= b[2] &&
      p[2] <= b[5];
  }
  for (int d = 0; d < 3; ++d)
  {
    if (!(p[d] >= b[d]))
    {
      return false;
    }
    if (!(p[d] < b[d + 3]) && !(p[d] == b[d + 3] && b[d + 3] == this->Domain[d + 3]))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkIdType vtkLRSplineElementLocator::FindElement(const double p[3], int* depth) const
{
  if (depth)
  {
    *depth = 0;
  }
  for (int d = 0; d < 3; ++d)
  {
    // also rejects NaN
    if (!(p[d] >= this->Domain[d] && p[d] <= this->Domain[d + 3]))
    {
      return -1;
    }
  }
  if (this->AllowOverlap)
  {
    std::vector<vtkIdType> candidates;
    this->FindCandidates(p, candidates);
    return candidates.empty() ? -1 : candidates[0];
  }
  vtkIdType element = -1;
  switch (this->Type)
  {
    case LINEAR:
    {
      const vtkIdType n = this->GetNumberOfElements();
      for (vtkIdType e = 0; e < n; ++e)
      {
        if (this->Contains(e, p))
        {
          return e;
        }
      }
      return -1;
    }
    case KD_TREE:
    case KD_FOREST:
    case TEXTURE:
    {
      const vtkIdType b =
        (this->BlockIndex(2, p[2]) * this->Blocks[1] + this->BlockIndex(1, p[1])) *
          this->Blocks[0] +
        this->BlockIndex(0, p[0]);
      Word w = this->Heads[b];
      if (!(w & LeafBit))
      {
        Word index = w;
        int steps = 0;
        for (;;)
        {
          const Word node = this->NodeWords[index];
          if (node & LeafBit)
          {
            w = node;
            break;
          }
          ++steps;
          const int dir = static_cast<int>((node >> 29) & 3u);
          index = p[dir] < this->NodeSplits[index] ? (node & ChildMask) : index + 1;
        }
        if (depth)
        {
          *depth = steps;
        }
      }
      element = (w == NoElement) ? -1 : static_cast<vtkIdType>(w & ElementMask);
      break;
    }
    case OCTREE:
    {
      double lo[3] = { this->Domain[0], this->Domain[1], this->Domain[2] };
      double hi[3] = { this->Domain[3], this->Domain[4], this->Domain[5] };
      Word w = this->OctreeNodes[0];
      int steps = 0;
      while (!(w & LeafBit))
      {
        int c = 0;
        for (int d = 0; d < 3; ++d)
        {
          const double mid = 0.5 * (lo[d] + hi[d]);
          if (p[d] >= mid)
          {
            c |= 1 << d;
            lo[d] = mid;
          }
          else
          {
            hi[d] = mid;
          }
        }
        w = this->OctreeNodes[w + c];
        ++steps;
      }
      if (depth)
      {
        *depth = steps;
      }
      element = (w == NoElement) ? -1 : static_cast<vtkIdType>(w & ElementMask);
      break;
    }
    default:
      return -1;
  }
  if (element >= 0 && !this->Contains(element, p))
  {
    return -1; // a hole (only in meshes that do not tile their bounding box)
  }
  return element;
}

//------------------------------------------------------------------------------
void vtkLRSplineElementLocator::FindElementsIntersecting(
  const double box[6], std::vector<vtkIdType>& out) const
{
  out.clear();
  auto meets = [&](vtkIdType e)
  {
    const double* b = this->Boxes.data() + 6 * e;
    for (int d = 0; d < 3; ++d)
    {
      if (!(b[d] < box[d + 3] && b[d + 3] > box[d]))
      {
        return false;
      }
    }
    return true;
  };
  if (this->Type != KD_TREE && this->Type != KD_FOREST && this->Type != TEXTURE)
  {
    const vtkIdType n = this->GetNumberOfElements();
    for (vtkIdType e = 0; e < n; ++e)
    {
      if (meets(e))
      {
        out.push_back(e);
      }
    }
    return;
  }
  int r[6];
  for (int d = 0; d < 3; ++d)
  {
    const std::vector<double>& E = this->Edges[d];
    const int nb = this->Blocks[d];
    r[d] = static_cast<int>(std::upper_bound(E.begin() + 1, E.end(), box[d]) - (E.begin() + 1));
    r[d + 3] =
      static_cast<int>(std::lower_bound(E.begin(), E.begin() + nb, box[d + 3]) - E.begin()) - 1;
    r[d] = std::max(0, std::min(r[d], nb - 1));
    r[d + 3] = std::max(0, std::min(r[d + 3], nb - 1));
    if (r[d] > r[d + 3])
    {
      return;
    }
  }
  std::vector<Word> stack;
  for (int k = r[2]; k <= r[5]; ++k)
  {
    for (int j = r[1]; j <= r[4]; ++j)
    {
      for (int i = r[0]; i <= r[3]; ++i)
      {
        const Word h =
          this->Heads[(static_cast<vtkIdType>(k) * this->Blocks[1] + j) * this->Blocks[0] + i];
        if (h & LeafBit)
        {
          if (h != NoElement && meets(h & ElementMask))
          {
            out.push_back(h & ElementMask);
          }
          continue;
        }
        stack.push_back(h);
        while (!stack.empty())
        {
          const Word index = stack.back();
          stack.pop_back();
          const Word node = this->NodeWords[index];
          if (node & LeafBit)
          {
            if (node != NoElement && meets(node & ElementMask))
            {
              out.push_back(node & ElementMask);
            }
            continue;
          }
          if (IsListWord(node))
          {
            for (Word k = 1; k <= (node & ChildMask); ++k)
            {
              const Word e = this->NodeWords[index + k] & ElementMask;
              if (meets(e))
              {
                out.push_back(e);
              }
            }
            continue;
          }
          const int dir = static_cast<int>((node >> 29) & 3u);
          const double s = this->NodeSplits[index];
          if (box[dir] < s)
          {
            stack.push_back(node & ChildMask);
          }
          if (box[dir + 3] > s)
          {
            stack.push_back(index + 1);
          }
        }
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

//------------------------------------------------------------------------------
void vtkLRSplineElementLocator::FindCandidates(const double p[3], std::vector<vtkIdType>& out) const
{
  out.clear();
  for (int d = 0; d < 3; ++d)
  {
    if (!(p[d] >= this->Domain[d] && p[d] <= this->Domain[d + 3]))
    {
      return; // also NaN
    }
  }
  if (this->Type != KD_TREE && this->Type != KD_FOREST && this->Type != TEXTURE)
  {
    const vtkIdType n = this->GetNumberOfElements();
    for (vtkIdType e = 0; e < n; ++e)
    {
      if (this->Contains(e, p))
      {
        out.push_back(e);
      }
    }
    return;
  }
  const vtkIdType b =
    (this->BlockIndex(2, p[2]) * this->Blocks[1] + this->BlockIndex(1, p[1])) * this->Blocks[0] +
    this->BlockIndex(0, p[0]);
  Word w = this->Heads[b];
  if (w & LeafBit)
  {
    if (w != NoElement && this->Contains(w & ElementMask, p))
    {
      out.push_back(w & ElementMask);
    }
    return;
  }
  Word index = w;
  for (;;)
  {
    const Word node = this->NodeWords[index];
    if (node & LeafBit)
    {
      if (node != NoElement && this->Contains(node & ElementMask, p))
      {
        out.push_back(node & ElementMask);
      }
      return;
    }
    if (IsListWord(node))
    {
      for (Word k = 1; k <= (node & ChildMask); ++k)
      {
        const Word e = this->NodeWords[index + k] & ElementMask;
        if (this->Contains(e, p))
        {
          out.push_back(e);
        }
      }
      return;
    }
    const int dir = static_cast<int>((node >> 29) & 3u);
    index = p[dir] < this->NodeSplits[index] ? (node & ChildMask) : index + 1;
  }
}
