#pragma once
// Small geometric worlds built in code for simulator tests.

#include "roomscout/sim/world.hpp"

namespace roomscout::sim::testing {

/// A closed square room [0, side]^2 with walls of `thickness` centred on its border.
inline World squareRoom(double side = 10.0, double thickness = 0.2) {
  World w;
  w.name = "square";
  w.source = "test:square";
  const Vec2 c[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
  for (int i = 0; i < 4; ++i) w.walls.push_back({c[i], c[(i + 1) % 4], thickness, 0.0, 2.5});
  w.start = {side / 2, side / 2, 0.0};
  w.start_given = true;
  w.rooms.push_back({1, "room", {c[0], c[1], c[2], c[3]}});
  return w;
}

/// Two rooms side by side ([0,6]x[0,5] and [6,12]x[0,5]) joined by a 1 m door at y = 2.5.
inline World twoRooms() {
  World w;
  w.name = "two_rooms";
  w.source = "test:two_rooms";
  const double t = 0.2;
  w.walls = {{{0, 0}, {12, 0}, t, 0, 2.5},  {{12, 0}, {12, 5}, t, 0, 2.5},
             {{12, 5}, {0, 5}, t, 0, 2.5},  {{0, 5}, {0, 0}, t, 0, 2.5},
             {{6, 0}, {6, 2.0}, t, 0, 2.5}, {{6, 3.0}, {6, 5}, t, 0, 2.5}};
  w.doors = {{{6, 2.5}, 1.0}};
  w.rooms = {{1, "west", {{0, 0}, {6, 0}, {6, 5}, {0, 5}}},
             {2, "east", {{6, 0}, {12, 0}, {12, 5}, {6, 5}}}};
  w.start = {2.0, 2.5, 0.0};
  w.start_given = true;
  return w;
}

/// Two 4 x 4 m rooms, [0,4]x[0,4] (south) and [0,4]x[4,8] (north), joined by a 0.8 m door in
/// the corner of the wall between them (x 3.1 to 3.9); the robot starts at (1.5, 1.5), from
/// where the door is seen at a slant.
inline World cornerDoorRooms() {
  World w;
  w.name = "corner_door";
  w.source = "test:corner_door";
  const double t = 0.2;
  w.walls = {{{0, 0}, {4, 0}, t, 0, 2.5},
             {{4, 0}, {4, 8}, t, 0, 2.5},
             {{4, 8}, {0, 8}, t, 0, 2.5},
             {{0, 8}, {0, 0}, t, 0, 2.5},
             {{0, 4}, {3.1, 4}, t, 0, 2.5}};
  w.doors = {{{3.5, 4}, 0.8}};
  w.rooms = {{1, "south", {{0, 0}, {4, 0}, {4, 4}, {0, 4}}},
             {2, "north", {{0, 4}, {4, 4}, {4, 8}, {0, 8}}}};
  w.start = {1.5, 1.5, 0.0};
  w.start_given = true;
  return w;
}

}  // namespace roomscout::sim::testing
