// prism render's deal of an animation's frames over MPI ranks (host/cli/frame_deal.h):
// every frame rendered once, whole or by one group, and no rank idle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "cli/frame_deal.h"

using prism_cli::dealFrames;
using prism_cli::FrameDeal;

TEST_CASE("an animation's frames are dealt so that every frame is rendered once and no part idles") {
  for (std::uint32_t frames : {1u, 2u, 3u, 5u, 6u, 7u, 12u, 100u}) {
    for (std::uint32_t parts : {1u, 2u, 3u, 4u, 7u, 8u}) {
      INFO(frames << " frames over " << parts << " parts");
      std::vector<int> whole_by(frames, 0);
      std::vector<std::vector<std::uint32_t>> group_parts(frames);  // parts sharing each frame, by place
      std::size_t most = 0, fewest = frames;
      for (std::uint32_t p = 0; p < parts; ++p) {
        const FrameDeal deal = dealFrames(frames, p, parts);
        for (std::size_t i = 0; i < deal.whole.size(); ++i) {
          REQUIRE(deal.whole[i] < frames);
          ++whole_by[deal.whole[i]];
          if (i > 0) CHECK(deal.whole[i] > deal.whole[i - 1]);
        }
        if (deal.shares) {
          REQUIRE(deal.shared_frame < frames);
          CHECK(deal.group_part < deal.group_parts);
          auto& g = group_parts[deal.shared_frame];
          if (g.size() <= deal.group_part) g.resize(deal.group_part + 1, parts);
          CHECK(g[deal.group_part] == parts);  // no place taken twice
          g[deal.group_part] = p;
          for (std::uint32_t f : deal.whole) CHECK(f < deal.shared_frame);  // shared frames come last
        }
        // Every part is busy until the frames left over: the whole frames differ by at most one.
        most = std::max(most, deal.whole.size());
        fewest = std::min(fewest, deal.whole.size());
        // No part sits out while there are frames left to share.
        CHECK((deal.shares || frames % parts == 0));
      }
      CHECK(most - fewest <= 1);
      for (std::uint32_t f = 0; f < frames; ++f) {
        const bool shared = !group_parts[f].empty();
        CHECK(whole_by[f] + (shared ? 1 : 0) == 1);  // each frame once, whole or shared
        if (shared) {
          const FrameDeal first = dealFrames(frames, group_parts[f][0], parts);
          CHECK(group_parts[f].size() == first.group_parts);
          for (std::uint32_t place = 0; place < group_parts[f].size(); ++place) {
            CHECK(group_parts[f][place] < parts);                                         // every place filled
            if (place > 0) CHECK(group_parts[f][place] > group_parts[f][place - 1]);  // in part order
          }
        }
      }
    }
  }
  // One frame over several parts: every part shares it, in order, as a still.
  for (std::uint32_t p = 0; p < 3; ++p) {
    const FrameDeal deal = dealFrames(1, p, 3);
    CHECK(deal.whole.empty());
    CHECK(deal.shares);
    CHECK(deal.group_part == p);
    CHECK(deal.group_parts == 3);
  }
  CHECK_THROWS_AS(dealFrames(4, 2, 2), std::invalid_argument);
}
