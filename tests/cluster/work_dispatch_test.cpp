// The dispatch hands out each tile's passes in turn, lowest pass first, never a tile's next pass
// while its last is out, and counts what is left.
#include "glint/cluster/work_dispatch.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(WorkDispatch, HandsOutEachTilesPassesInTurnLowestPassFirst) {
    WorkDispatch dispatch({0, 0, 1}, 2);  // tile 2 has done its first pass
    EXPECT_EQ(dispatch.left(), 5);
    EXPECT_EQ(dispatch.passes_done(), 0);
    const std::vector<WorkPiece> first = dispatch.take(2);
    EXPECT_EQ(first, (std::vector<WorkPiece>{{0, 0}, {0, 1}}));
    // Tile 0's second pass waits for its first.
    EXPECT_EQ(dispatch.take(5), (std::vector<WorkPiece>{{1, 2}}));
    EXPECT_TRUE(dispatch.take(5).empty());
    EXPECT_EQ(dispatch.in_flight(), 3);
    dispatch.finish({0, 0});
    EXPECT_EQ(dispatch.take(5), (std::vector<WorkPiece>{{1, 0}}));
    dispatch.give_back({{0, 1}});
    EXPECT_EQ(dispatch.take(5), (std::vector<WorkPiece>{{0, 1}}));
    EXPECT_THROW(dispatch.finish({1, 1}), std::logic_error);
    for (const WorkPiece p : {WorkPiece{0, 1}, WorkPiece{1, 2}, WorkPiece{1, 0}})
        dispatch.finish(p);
    EXPECT_EQ(dispatch.passes_done(), 1);
    EXPECT_EQ(dispatch.take(5), (std::vector<WorkPiece>{{1, 1}}));
    dispatch.finish({1, 1});
    EXPECT_TRUE(dispatch.done());
    EXPECT_EQ(dispatch.passes_done(), 2);
}

}  // namespace
}  // namespace glint
