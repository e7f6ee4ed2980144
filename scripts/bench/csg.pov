// POV-Ray 3.7 twin of scenes/csg.ron (lens, die, hollow cube on a mirror floor, two
// lights), for scripts/bench_povray_csg.sh. raylab's right-handed coordinates are
// mirrored in z for POV-Ray's left-handed ones (so rotations about x and y turn the other
// way); Phong terms map to finish ambient/diffuse/phong/reflection, raylab's 1/d^2
// light falloff to fade_power 2; assumed_gamma 2.2 writes the colours as computed, as raylab does.
global_settings { assumed_gamma 2.2 max_trace_level 6 ambient_light rgb <1, 1, 1> }
background { rgb <0.05, 0.06, 0.09> }
camera {
  perspective
  location <0.0, 3.2, -8.0>
  look_at <0.0, 0.7, -0.0>
  right x*4/3
  angle 51.77  // horizontal; raylab's vertical fov 40 at 4:3
}
#declare Ambient = <0.2, 0.2, 0.22>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor  = texture { Mat(<0.15,0.15,0.17>, <0.5,0.5,0.53>, <0.1,0.1,0.1>, 8, 0.25) }
#declare T_ivory  = texture { Mat(<0.35,0.33,0.3>, <0.85,0.82,0.75>, <0.5,0.5,0.5>, 80, 0) }
#declare T_pip    = texture { Mat(<0.05,0.02,0.02>, <0.5,0.05,0.05>, <0.3,0.3,0.3>, 30, 0) }
#declare T_glass  = texture { Mat(<0.02,0.04,0.06>, <0.1,0.2,0.3>, <0.9,0.9,0.9>, 300, 0.65) }
#declare T_copper = texture { Mat(<0.25,0.12,0.06>, <0.7,0.35,0.15>, <0.8,0.6,0.4>, 50, 0.06) }
#declare T_inner  = texture { Mat(<0.1,0.2,0.1>, <0.2,0.6,0.25>, <0.2,0.2,0.2>, 20, 0) }
light_source { <-4.0, 6.0, -5.0> rgb <1.0, 0.97, 0.9>*20 fade_distance 1 fade_power 2 }
light_source { <5.0, 4.0, -2.0> rgb <0.8, 0.85, 1.0>*10 fade_distance 1 fade_power 2 }

box { <-10, -1e-4, -10>, <10, 0, 10> texture { T_floor } }

intersection {  // lens
  sphere { <0, 0, 0.75>, 1 }
  sphere { <0, 0, -0.75>, 1 }
  texture { T_glass }
  scale 1.4 rotate <0, 0, 0> rotate <0, -62, 0> rotate <0, 0, 0> translate <-2.4, 1.0, -0.3>
}

difference {  // die: a rounded cube with 21 pips cut out
  intersection { box { -1, 1 } sphere { 0, 1.5 } texture { T_ivory } }
      sphere { <0, 0, -1.07>, 0.17 texture { T_pip } }
      sphere { <-0.5, -0.5, 1.07>, 0.17 texture { T_pip } }
      sphere { <-0.5, 0, 1.07>, 0.17 texture { T_pip } }
      sphere { <-0.5, 0.5, 1.07>, 0.17 texture { T_pip } }
      sphere { <0.5, -0.5, 1.07>, 0.17 texture { T_pip } }
      sphere { <0.5, 0, 1.07>, 0.17 texture { T_pip } }
      sphere { <0.5, 0.5, 1.07>, 0.17 texture { T_pip } }
      sphere { <1.07, -0.5, 0.5>, 0.17 texture { T_pip } }
      sphere { <1.07, 0.5, -0.5>, 0.17 texture { T_pip } }
      sphere { <-1.07, -0.5, 0.5>, 0.17 texture { T_pip } }
      sphere { <-1.07, -0.5, -0.5>, 0.17 texture { T_pip } }
      sphere { <-1.07, 0.5, 0.5>, 0.17 texture { T_pip } }
      sphere { <-1.07, 0.5, -0.5>, 0.17 texture { T_pip } }
      sphere { <-1.07, 0, 0>, 0.17 texture { T_pip } }
      sphere { <-0.5, 1.07, 0.5>, 0.17 texture { T_pip } }
      sphere { <0, 1.07, 0>, 0.17 texture { T_pip } }
      sphere { <0.5, 1.07, -0.5>, 0.17 texture { T_pip } }
      sphere { <-0.5, -1.07, 0.5>, 0.17 texture { T_pip } }
      sphere { <-0.5, -1.07, -0.5>, 0.17 texture { T_pip } }
      sphere { <0.5, -1.07, 0.5>, 0.17 texture { T_pip } }
      sphere { <0.5, -1.07, -0.5>, 0.17 texture { T_pip } }
  scale 0.7 rotate <20, 0, 0> rotate <0, -35, 0> rotate <0, 0, 0> translate <0.0, 0.75, -0.8>
}

difference {  // hollow cube with round windows
  box { -1, 1 texture { T_copper } }
  box { -0.85, 0.85 texture { T_inner } }
  cylinder { <0, 0, -1.5>, <0, 0, 1.5>, 0.6 texture { T_inner } rotate <0, -90, 0> }
  cylinder { <0, 0, -1.5>, <0, 0, 1.5>, 0.6 texture { T_inner } rotate <-90, 0, 0> }
  cylinder { <0, 0, -1.5>, <0, 0, 1.5>, 0.6 texture { T_inner } }
  scale 0.9 rotate <0, 0, 0> rotate <0, 25, 0> rotate <0, 0, 0> translate <2.4, 0.9, 0.2>
}
