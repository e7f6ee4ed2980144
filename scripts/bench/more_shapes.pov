// POV-Ray 3.7 twin of scenes/more_shapes.ron (the eight unit shapes: the course's five,
// tori, tubes and octahedra, on a mirror floor under a point light and a spot), for
// scripts/bench_povray.sh. Each object is placed by the matrix of its raylab transform,
// mirrored in z for POV-Ray's left-handed coordinates; POV-Ray's torus (axis y) has y and
// z swapped into raylab's (axis z); a tube is POV-Ray's difference of two cylinders and
// an octahedron the intersection of eight planes, as a student's POV-Ray scene would
// write them. Phong terms map to finish ambient/diffuse/phong/reflection, raylab's 1/d^2
// light falloff to fade_power 2 (POV-Ray fades by 2 / (1 + d^2), so intensities are halved); assumed_gamma 2.2 writes the colours as computed.
global_settings { assumed_gamma 2.2 max_trace_level 4 ambient_light rgb <1, 1, 1> }
background { rgb <0.04, 0.05, 0.08> }
camera {
  perspective
  location <0.0, 3.4, -9.0>
  look_at <0.0, 0.8, -0.0>
  right x*4/3
  angle 51.77  // horizontal; raylab's vertical fov 40 at 4:3
}
#declare Ambient = <0.2, 0.2, 0.22>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor  = texture { Mat(<0.1,0.1,0.11>, <0.45,0.45,0.48>, <0.1,0.1,0.1>, 8, 0.25) }
#declare T_clay   = texture { Mat(<0.15,0.1,0.08>, <0.8,0.55,0.4>, <0.4,0.4,0.4>, 30, 0) }
#declare T_teal   = texture { Mat(<0.05,0.15,0.15>, <0.2,0.65,0.65>, <0.5,0.5,0.5>, 50, 0) }
#declare T_gold   = texture { Mat(<0.2,0.15,0.05>, <0.75,0.55,0.15>, <0.9,0.8,0.5>, 80, <0.2,0.15,0.05>) }
#declare T_chrome = texture { Mat(<0.05,0.05,0.05>, <0.1,0.1,0.1>, <0.9,0.9,0.9>, 200, 0.7) }
#declare T_violet = texture { Mat(<0.1,0.05,0.15>, <0.5,0.3,0.75>, <0.5,0.5,0.5>, 60, 0) }
light_source { <-4.0, 6.0, -5.0> rgb <1.0, 0.97, 0.9>*45/2 fade_distance 1 fade_power 2 }
light_source {
  <4.0, 5.0, -3.0> rgb <0.8, 0.85, 1.0>*30/2 fade_distance 1 fade_power 2
  spotlight radius 30 falloff 30 point_at <4.0 - 0.7, 5.0 - 1.0, -3.0 + 0.6>
}

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor }
  matrix <12, 0, 0, 0, 7.34788079e-16, 12, 0, 1, -6.123234e-17, 0, 0, 0>
}
sphere { 0, 1  // sphere
  texture { T_clay }
  matrix <0.7, 0, 0, 0, 0.7, 0, 0, 0, -0.7, -3.6, 0.7, 2.5>
}
box { -1, 1  // cube
  texture { T_teal }
  matrix <0.519615242, 0, 0.3, 0, 0.6, 0, 0.3, 0, -0.519615242, -1.8, 0.6, 2.8>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // cylinder
  texture { T_clay }
  matrix <0.55, 0, 0, 0, 3.3677787e-17, 0.55, 0, 0.8, -4.8985872e-17, 0, 0.8, 2.8>
}
cone { <0, 0, 0>, 0, <0, 0, 1>, 1  // cone
  texture { T_teal }
  matrix <0.6, 0, 0, 0, 3.6739404e-17, -0.6, 0, -1.4, -8.57252759e-17, 1.8, 1.4, 2.8>
}
polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // square
  texture { T_violet }
  matrix <0.606217783, 0, -0.35, 0, 0.7, 0, -0.5, 0, -0.866025404, 3.6, 0.8, 2.8>
}
torus { 1, 0.25  // flat ring
  texture { T_gold }
  matrix <0.9, 0, 0, 0, 0.9, -5.5109106e-17, 0, 5.5109106e-17, 0.9, -3, 0.25, -0.5>
}
torus { 1, 0.3  // standing ring
  texture { T_chrome }
  matrix <0.655321635, 0, 0.458861149, 0.458861149, 0, -0.655321635, 0, 0.8, 0, -0.9, 1.04, -0.2>
}
torus { 1, 1.3  // spindle
  texture { T_violet }
  matrix <0.3, 0, 0, 0, 0.42, -2.57175828e-17, 0, 1.8369702e-17, 0.3, 1.1, 0.55, -1.3>
}
difference { cylinder { <0, 0, -1>, <0, 0, 1>, 1 } cylinder { <0, 0, -1.001>, <0, 0, 1.001>, 0.7 }  // pipe
  texture { T_clay }
  matrix <0.321393805, 0, 0.383022222, 0, 0.5, 0, 0.689439999, 0, -0.578508849, 2.9, 0.5, -0.4>
}
difference { cylinder { <0, 0, -1>, <0, 0, 1>, 1 } cylinder { <0, 0, -1.001>, <0, 0, 1.001>, 0.45 }  // collar
  texture { T_teal }
  matrix <0.6, 0, 0, 0, 3.6739404e-17, 0.6, 0, 0.2, -1.2246468e-17, -1.6, 0.2, -2.3>
}
intersection { plane { <1, 1, 1>, 0.577350269 } plane { <1, 1, -1>, 0.577350269 } plane { <1, -1, 1>, 0.577350269 } plane { <1, -1, -1>, 0.577350269 } plane { <-1, 1, 1>, 0.577350269 } plane { <-1, 1, -1>, 0.577350269 } plane { <-1, -1, 1>, 0.577350269 } plane { <-1, -1, -1>, 0.577350269 }  // octahedron
  texture { T_gold }
  matrix <0.657784835, 0, 0.2394141, 0, 0.7, 0, 0.2394141, 0, -0.657784835, 0.9, 0.7, 0.6>
}
intersection { plane { <1, 1, 1>, 0.577350269 } plane { <1, 1, -1>, 0.577350269 } plane { <1, -1, 1>, 0.577350269 } plane { <1, -1, -1>, 0.577350269 } plane { <-1, 1, 1>, 0.577350269 } plane { <-1, 1, -1>, 0.577350269 } plane { <-1, -1, 1>, 0.577350269 } plane { <-1, -1, -1>, 0.577350269 }  // small octahedron
  texture { T_chrome }
  matrix <0.243727484, 0.243727484, 0.0607768622, -0.192842487, 0.235818218, -0.172341357, 0.160961762, -0.0865256116, -0.298503986, 0.4, 0.35, -2.5>
}
