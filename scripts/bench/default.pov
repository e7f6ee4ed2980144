// POV-Ray 3.7 twin of scenes/default.ron (raylab's showcase: a red, a mirror, a blue box,
// a green pillar and a gold cone on a mirror floor; a point, a directional and a spot
// light), for scripts/bench_povray.sh. raylab's right-handed coordinates are mirrored in
// z for POV-Ray's left-handed ones (rotations about x and y turn the other way, the cone
// opens towards -z); Phong terms map to finish ambient/diffuse/phong/reflection, raylab's
// 1/d^2 falloff to fade_power 2 (POV-Ray fades by 2 / (1 + d^2), so intensities are
// halved); raylab's hard-edged spot is POV-Ray's spotlight with radius = falloff (POV-Ray
// softens nothing between the two); assumed_gamma 2.2 writes the colours as computed.
// Differences that stay: raylab's specular colour is a colour, POV-Ray's phong a grey
// amount (vlength(S)/sqrt(3)); the gold's is therefore a little whiter.
global_settings { assumed_gamma 2.2 max_trace_level 6 ambient_light rgb <1, 1, 1> }
background { rgb <0.05, 0.06, 0.09> }
camera {
  perspective
  location <0.0, 2.6, -8.5>
  look_at <0.0, 0.9, 0.0>
  right x*4/3
  angle 49.32  // horizontal; raylab's vertical fov 38 at 4:3
}
#declare Ambient = <0.15, 0.15, 0.17>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor  = texture { Mat(<0.2,0.2,0.22>, <0.55,0.55,0.58>, <0.1,0.1,0.1>, 8, <0.12,0.12,0.12>) }
#declare T_red    = texture { Mat(<0.5,0.06,0.05>, <0.75,0.1,0.08>, <0.6,0.6,0.6>, 60, 0) }
#declare T_mirror = texture { Mat(<0.02,0.02,0.02>, <0.05,0.05,0.05>, <0.9,0.9,0.9>, 400, <0.85,0.85,0.88>) }
#declare T_blue   = texture { Mat(<0.06,0.12,0.4>, <0.12,0.25,0.75>, <0.35,0.35,0.4>, 20, 0) }
#declare T_green  = texture { Mat(<0.06,0.3,0.12>, <0.12,0.6,0.25>, <0.7,0.7,0.7>, 120, <0.08,0.12,0.08>) }
#declare T_gold   = texture { Mat(<0.3,0.22,0.05>, <0.6,0.45,0.1>, <0.9,0.75,0.35>, 40, <0.25,0.2,0.08>) }
light_source { <-4.0, 6.0, -5.0> rgb <1.0, 0.95, 0.9>*38/2 fade_distance 1 fade_power 2 }
light_source { <-0.6, 1.0, -0.4>*1000 rgb <0.35, 0.4, 0.55> parallel point_at <0, 0, 0> }
light_source {
  <3.0, 5.0, -2.0> rgb <1.0, 0.8, 0.55>*20/2 fade_distance 1 fade_power 2
  spotlight radius 22 falloff 22 point_at <3.0 - 0.45, 5.0 - 1.0, -2.0 + 0.35>
}

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor } scale <9, 9, 1> rotate <90, 0, 0>
}
sphere { <-1.7, 0.8, -0.6>, 0.8 texture { T_red } }  // red ball
sphere { <0.35, 1.0, 1.0>, 1 texture { T_mirror } }  // mirror ball
box { -1, 1  // blue box
  texture { T_blue } scale 0.55 rotate <0, -30, 0> translate <2.2, 0.55, -0.5>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // green pillar
  texture { T_green } scale <0.45, 0.45, 1.1> rotate <90, 0, 0> translate <-3.0, 1.1, 1.8>
}
cone { <0, 0, 0>, 0, <0, 0, -1>, 1  // gold cone
  texture { T_gold } scale <0.5, 0.5, 1.2> rotate <-90, 0, 0> translate <0.7, 1.2, -1.6>
}
