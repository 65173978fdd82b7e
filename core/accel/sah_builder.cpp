#include "core/accel/sah_builder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace prism {

namespace {

struct Task {
  std::uint32_t node, begin, end;
  int depth;
};

struct Bin {
  Aabb box;
  std::uint32_t count = 0, packed = 0; // packed: of count, those tested in packets
};

class Builder {
public:
  Builder(const std::vector<Aabb>& boxes, const SahOptions& options,
          const std::vector<bool>& packed)
      : boxes_(boxes), packed_(packed), options_(options), bins_(std::max(2, options.bins)) {
    centroids_.reserve(boxes.size());
    for (const Aabb& b : boxes) {
      // An unbounded box has no centre; 0 keeps the binning arithmetic finite.
      Vec3 c = b.centroid();
      for (int a = 0; a < 3; ++a)
        if (!std::isfinite(c[a])) c[a] = 0.0;
      centroids_.push_back(c);
    }
  }

  SahTree build() {
    SahTree tree;
    if (boxes_.empty()) return tree;
    tree.order.resize(boxes_.size());
    for (std::uint32_t i = 0; i < tree.order.size(); ++i)
      tree.order[i] = i;
    tree.nodes.reserve(2 * boxes_.size() / std::max<std::uint32_t>(1, options_.maxLeaf / 2) + 1);
    tree.nodes.emplace_back();
    std::vector<Task> tasks{{0, 0, std::uint32_t(boxes_.size()), 1}};
    while (!tasks.empty()) {
      const Task task = tasks.back();
      tasks.pop_back();
      split(tree, task, tasks);
    }
    return tree;
  }

private:
  // Decides whether tree.nodes[task.node] is a leaf or splits it, queueing the
  // children.
  void split(SahTree& tree, const Task& task, std::vector<Task>& tasks) {
    std::uint32_t* order = tree.order.data();
    Aabb box, centres;
    std::uint32_t packed = 0;
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
      box.extend(boxes_[order[i]]);
      centres.extend(centroids_[order[i]]);
      packed += isPacked(order[i]);
    }
    tree.nodes[task.node].box = box;
    const std::uint32_t count = task.end - task.begin;
    auto makeLeaf = [&] {
      tree.nodes[task.node].first = task.begin;
      tree.nodes[task.node].count = count;
      tree.depth = std::max(tree.depth, task.depth);
    };
    if (count == 1) return makeLeaf();

    std::uint32_t mid = task.begin;
    if (task.depth <= options_.maxSahDepth) {
      int axis = -1, splitBin = 0;
      const double cost = bestSplit(tree.order, task, box, centres, axis, splitBin);
      const double leafCost = options_.intersectCost * tests(count, packed);
      if (count <= options_.maxLeaf && !(cost < leafCost)) return makeLeaf();
      if (axis >= 0) {
        const double lo = centres.lo[axis], scale = binScale(centres, axis);
        mid =
            std::uint32_t(std::partition(order + task.begin, order + task.end,
                                         [&](std::uint32_t i) {
                                           return binOf(centroids_[i][axis], lo, scale) < splitBin;
                                         }) -
                          order);
      }
    } else if (count <= options_.maxLeaf) {
      return makeLeaf();
    }
    if (mid == task.begin || mid == task.end) mid = medianSplit(order, task, centres);

    const auto left = std::uint32_t(tree.nodes.size());
    tree.nodes.emplace_back();
    tree.nodes.emplace_back();
    tree.nodes[task.node].left = left;
    tree.nodes[task.node].right = left + 1;
    tasks.push_back({left + 1, mid, task.end, task.depth + 1});
    tasks.push_back({left, task.begin, mid, task.depth + 1});
  }

  double binScale(const Aabb& centres, int axis) const {
    const double extent = centres.hi[axis] - centres.lo[axis];
    // Slightly under bins/extent so the largest centroid still lands in the last bin.
    return double(bins_) * (1.0 - 1e-6) / extent;
  }

  // 1 where box i's primitive is tested in packets, else 0.
  std::uint32_t isPacked(std::uint32_t i) const { return !packed_.empty() && packed_[i] ? 1 : 0; }

  // What testing `count` primitives costs, `packed` of them in packets,
  // in units of one primitive's test.
  double tests(std::uint32_t count, std::uint32_t packed) const {
    const std::uint32_t size = std::max<std::uint32_t>(1, options_.packetSize);
    const std::uint32_t packets = (packed + size - 1) / size;
    return double(count - packed) + options_.packetCost * double(packets);
  }

  int binOf(double c, double lo, double scale) const {
    const int b = int((c - lo) * scale);
    return std::clamp(b, 0, bins_ - 1);
  }

  // The cheapest split over all axes and bin borders: returns its cost (relative
  // to one box test) and sets axis/splitBin, or leaves axis at -1 if the
  // centroids cannot be told apart.
  double bestSplit(const std::vector<std::uint32_t>& order, const Task& task, const Aabb& box,
                   const Aabb& centres, int& axis, int& splitBin) {
    double best = std::numeric_limits<double>::infinity();
    const double parentArea = box.halfArea();
    std::vector<double>& rightCost = costScratch_;
    rightCost.assign(std::size_t(bins_), 0.0);
    // All three axes are binned in one pass over the items (each item's box
    // and centroid are read once).
    bool usable[3];
    double lo[3], scale[3];
    for (int a = 0; a < 3; ++a) {
      const double extent = centres.hi[a] - centres.lo[a];
      usable[a] = extent > 0.0 && std::isfinite(extent);
      lo[a] = centres.lo[a];
      scale[a] = usable[a] ? binScale(centres, a) : 0.0;
      binScratch_[std::size_t(a)].assign(std::size_t(bins_), Bin{});
    }
    for (std::uint32_t i = task.begin; i < task.end; ++i) {
      const Vec3& c = centroids_[order[i]];
      const Aabb& b = boxes_[order[i]];
      const std::uint32_t packed = isPacked(order[i]);
      for (int a = 0; a < 3; ++a) {
        Bin& bin = binScratch_[std::size_t(a)][std::size_t(binOf(c[a], lo[a], scale[a]))];
        bin.box.extend(b);
        ++bin.count;
        bin.packed += packed;
      }
    }
    for (int a = 0; a < 3; ++a) {
      if (!usable[a]) continue;
      const std::vector<Bin>& bins = binScratch_[std::size_t(a)];
      // rightCost[k]: area x the cost of testing bins k.. (the right side of
      // border k).
      Aabb right;
      std::uint32_t rightCount = 0, rightPacked = 0;
      for (int k = bins_ - 1; k > 0; --k) {
        right.extend(bins[std::size_t(k)].box);
        rightCount += bins[std::size_t(k)].count;
        rightPacked += bins[std::size_t(k)].packed;
        rightCost[std::size_t(k)] = right.halfArea() * tests(rightCount, rightPacked);
      }
      Aabb left;
      std::uint32_t leftCount = 0, leftPacked = 0;
      for (int k = 1; k < bins_; ++k) {
        left.extend(bins[std::size_t(k - 1)].box);
        leftCount += bins[std::size_t(k - 1)].count;
        leftPacked += bins[std::size_t(k - 1)].packed;
        const std::uint32_t count = task.end - task.begin;
        if (leftCount == 0 || leftCount == count) continue;
        const double cost =
            1.0 + options_.intersectCost *
                      (left.halfArea() * tests(leftCount, leftPacked) + rightCost[std::size_t(k)]) /
                      parentArea;
        if (cost < best) {
          best = cost;
          axis = a;
          splitBin = k;
        }
      }
    }
    return best;
  }

  // Splits at the middle of the range along the centroids' longest axis.
  std::uint32_t medianSplit(std::uint32_t* order, const Task& task, const Aabb& centres) const {
    const Vec3 e = centres.extent();
    const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    const std::uint32_t mid = task.begin + (task.end - task.begin) / 2;
    std::nth_element(order + task.begin, order + mid, order + task.end,
                     [&](std::uint32_t a, std::uint32_t b) {
                       return centroids_[a][axis] < centroids_[b][axis];
                     });
    return mid;
  }

  const std::vector<Aabb>& boxes_;
  const std::vector<bool>& packed_;
  SahOptions options_;
  int bins_;
  std::vector<Vec3> centroids_;
  std::vector<Bin> binScratch_[3];
  std::vector<double> costScratch_;
};

} // namespace

SahTree buildSahTree(const std::vector<Aabb>& boxes, const SahOptions& options,
                     const std::vector<bool>& packed) {
  return Builder(boxes, options, packed).build();
}

} // namespace prism
