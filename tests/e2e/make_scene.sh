#!/usr/bin/env bash
# Writes the e2e test scene as a Wavefront OBJ (z up) to $1: a 16 m x 12 m yard (on a ground
# slab 1.5 m larger all round, so views at the yard's edge leave room for the robot body) with a
# 4 m x 4 m room (2.5 m walls, a 2 m doorway on the south side), a parked box (vehicle-like)
# and two stones. Small enough for a two-robot team to explore in about a minute of sim time.
set -euo pipefail
out=$1
nv=0
{
  echo "# hexplore e2e scene: yard and room"
  # box XMIN YMIN ZMIN XMAX YMAX ZMAX: an axis-aligned closed box (12 triangles).
  box() {
    local x0=$1 y0=$2 z0=$3 x1=$4 y1=$5 z1=$6
    echo "v $x0 $y0 $z0"; echo "v $x1 $y0 $z0"; echo "v $x1 $y1 $z0"; echo "v $x0 $y1 $z0"
    echo "v $x0 $y0 $z1"; echo "v $x1 $y0 $z1"; echo "v $x1 $y1 $z1"; echo "v $x0 $y1 $z1"
    local b=$nv
    local f
    for f in "1 3 2" "1 4 3" "5 6 7" "5 7 8" "1 2 6" "1 6 5" "2 3 7" "2 7 6" "3 4 8" "3 8 7" "4 1 5" "4 5 8"; do
      set -- $f
      echo "f $((b + $1)) $((b + $2)) $((b + $3))"
    done
    nv=$((nv + 8))
  }
  # Ground: a thin slab whose top is z = 0.
  box -4.5 -4.5 -0.2 14.5 10.5 0
  # Room x 6..10, y 3..7, walls 0.2 m thick and 2.5 m high; doorway x 7..9 in the south wall
  # (paths follow supervoxel centres, not the doorway's middle: a narrow one blocks robots).
  box 6 3 0 7 3.2 2.5
  box 9 3 0 10 3.2 2.5
  box 6 6.8 0 10 7 2.5
  box 6 3.2 0 6.2 6.8 2.5
  box 9.8 3.2 0 10 6.8 2.5
  box 6 3 2.3 10 7 2.5
  # A parked vehicle-sized box and two stones in the yard.
  box 1 5 0 3.5 6.8 1.5
  box 11 0 0 11.6 0.5 0.4
  box 3.5 1.8 0 4.0 2.3 0.5
} > "$out"
