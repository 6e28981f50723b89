// Splitting a length into cells as CGA's split does (issue 15): a facade's
// height into floors, a floor's width into bays. A spec is a list of sizes:
//
//   3      a cell of 3 m
//   ~3     a flexible cell: about 3 m, stretched or shrunk with the other
//          flexible cells so that the cells fill the length exactly
//   _1     a gap of 1 m (a margin, a plinth): takes room, is no tile
//   _~1    a flexible gap
//   {...}* the group repeated as often as it fits (rounded to the nearest
//          count when it holds a flexible size, else down)
//   {...}*4  the group exactly 4 times
//   name   a size given by name (Facade Split's floor_height, bay_width),
//          so a number parameter, which an expression can drive, sets it;
//          also ~name, _name, _~name
//
// At most one repeated group, not nested. Without flexible sizes the cells
// are laid from the start and what does not fit is left over at the end (the
// caller drops cells that leave the face), e.g. "4 {3}*" over 14 m: 4, 3, 3,
// 3 and 1 m spare; "_1 {~3}* _1" over 14 m: a 1 m margin, 4 bays of 3 m, a 1 m
// margin.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace procex {

struct SplitItem {
  double size = 0.0;
  bool flexible = false;
  bool gap = false;
};

struct SplitSpec {
  std::vector<SplitItem> before, repeated, after;
  bool has_repeat = false;
  int count = -1;  // the repeated group's count; -1: as often as it fits
};

// The sizes a spec may give by name, and their values in metres.
using SplitNames = std::map<std::string, double, std::less<>>;

// Throws PlacementError naming the character where `text` goes wrong (or the
// unknown name, with the names `names` knows).
SplitSpec parse_split(std::string_view text, const SplitNames& names = {});

struct SplitCell {
  double start = 0.0, size = 0.0;
  int index = -1;  // among the tiles (gaps are -1), from the start
};

// The cells of `spec` over [0, length]; cells of size zero are left out.
// Throws PlacementError for more than kMaxRepeatItems cells.
std::vector<SplitCell> split_length(const SplitSpec& spec, double length);

}  // namespace procex
