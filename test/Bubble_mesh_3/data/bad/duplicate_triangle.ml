GOCAD Model3d 1
# Bad model: surface 'copy' repeats the top triangle 5 6 7 of the cube's skin
# (a surface exported twice): a duplicate triangle.
HEADER {
name: duplicate_triangle
}
GOCAD_ORIGINAL_COORDINATE_SYSTEM
NAME Default
ZPOSITIVE Elevation
END_ORIGINAL_COORDINATE_SYSTEM
TSURF skin
TSURF copy
TFACE 1  boundary skin
  0 0 1
  1 0 1
  1 1 1
TFACE 2  fault copy
  0 0 1
  1 0 1
  1 1 1
REGION 3  Universe
  +1  0
REGION 4  Cube
  -1  +2  -2  0
END
GOCAD TSurf 1
HEADER {
name: skin
}
TFACE
VRTX 1 0 0 0
VRTX 2 1 0 0
VRTX 3 1 1 0
VRTX 4 0 1 0
VRTX 5 0 0 1
VRTX 6 1 0 1
VRTX 7 1 1 1
VRTX 8 0 1 1
TRGL 1 3 2
TRGL 1 4 3
TRGL 5 6 7
TRGL 5 7 8
TRGL 1 2 6
TRGL 1 6 5
TRGL 4 8 7
TRGL 4 7 3
TRGL 1 5 8
TRGL 1 8 4
TRGL 2 3 7
TRGL 2 7 6
END
GOCAD TSurf 1
HEADER {
name: copy
}
TFACE
VRTX 1 0 0 1
VRTX 2 1 0 1
VRTX 3 1 1 1
TRGL 1 2 3
END
