// PCCD/Kinetic/internal/Query_memo_pool.h -- the memo tables through which the kinetic AABB tree's
// queries read vertex positions and node boxes at the query time (doc/algorithms.md, "Kinetic AABB tree": "the box
// at time t is read off those vertices' positions"), kept for reuse between queries.
//
// A query needs one position per vertex and one box per node, each computed at most once. Fresh
// tables per query cost an allocation of the size of the tree and clearing it, a sizeable part of
// a query that visits much of the tree. Here every entry carries a stamp and is valid when its stamp
// equals the table's current one, so starting a query clears nothing; the tables go back to a pool
// owned by the tree, one set per query running at the same time, so const queries stay safe for
// concurrent callers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace PCCD::internal {

/// Per vertex a position, per node a box, each valid when its stamp equals `stamp` (stamp and
/// value side by side, so a look-up touches one place).
struct Query_memo {
    struct Position {
        Eigen::Vector3d value;
        std::uint32_t stamp = 0;
    };
    struct Box {
        Eigen::AlignedBox3d value;
        std::uint32_t stamp = 0;
    };
    std::vector<Position> positions;
    std::vector<Box> boxes;
    std::uint32_t stamp = 0;

    /// Invalidates every entry, for a tree of `vertices` vertices and `nodes` node slots. O(1)
    /// unless the tree grew (or once every 2^32 queries).
    void start(std::size_t vertices, std::size_t nodes)
    {
        if (positions.size() < vertices) positions.resize(vertices);
        if (boxes.size() < nodes) boxes.resize(nodes);
        if (++stamp == 0) {
            for (Position& p : positions) p.stamp = 0;
            for (Box& b : boxes) b.stamp = 0;
            stamp = 1;
        }
    }
};

/// Query_memo tables free for reuse. Thread-safe; copying or assigning gives an empty pool (the
/// tables belong to one tree and are sized for it).
class Query_memo_pool {
public:
    Query_memo_pool() = default;
    Query_memo_pool(const Query_memo_pool&) {}
    Query_memo_pool& operator=(const Query_memo_pool&) { return *this; }

    /// A free memo, or a new one.
    std::unique_ptr<Query_memo> acquire() const
    {
        const std::lock_guard lock(m_mutex);
        if (m_free.empty()) return std::make_unique<Query_memo>();
        std::unique_ptr<Query_memo> memo = std::move(m_free.back());
        m_free.pop_back();
        return memo;
    }
    /// Gives `memo` back for the next query.
    void release(std::unique_ptr<Query_memo> memo) const
    {
        const std::lock_guard lock(m_mutex);
        m_free.push_back(std::move(memo));
    }

private:
    mutable std::mutex m_mutex;
    mutable std::vector<std::unique_ptr<Query_memo>> m_free;
};

} // namespace PCCD::internal
