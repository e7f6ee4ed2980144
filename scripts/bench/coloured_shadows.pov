// POV-Ray 3.7 twin of scenes/coloured_shadows.ron (a post and a ball on a white floor
// under a red, a green and a blue point light), for scripts/bench_povray.sh.
// raylab's right-handed coordinates are mirrored in z for POV-Ray's left-handed ones
// (rotations about x and y turn the other way); Phong terms map to finish
// ambient/diffuse/phong, raylab's 1/d^2 falloff to fade_power 2 (POV-Ray fades by
// 2 / (1 + d^2): intensities are halved, and lights nearer than a few units differ by a
// few per cent); assumed_gamma 2.2 writes the colours as computed. max_depth 0: camera
// rays only (max_trace_level 1).
global_settings { assumed_gamma 2.2 max_trace_level 1 ambient_light rgb <1, 1, 1> }
background { rgb <0, 0, 0> }
camera {
  perspective
  location <0.0, 6.0, -7.0>
  look_at <0.0, 0.5, 0.0>
  right x*4/3
  angle 51.774  // horizontal; raylab's vertical fov 40 at 4:3
}
#declare Ambient = <0.1, 0.1, 0.1>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor = texture { Mat(<0.1,0.1,0.1>, <0.9,0.9,0.9>, <0,0,0>, 1, 0) }
#declare T_grey  = texture { Mat(<0.1,0.1,0.1>, <0.6,0.6,0.6>, <0.3,0.3,0.3>, 20, 0) }
light_source { <-3.0, 4.0, -2.0> rgb <1, 0, 0>*25/2 fade_distance 1 fade_power 2 }
light_source { <3.0, 4.0, -2.5> rgb <0, 1, 0>*25/2 fade_distance 1 fade_power 2 }
light_source { <0.0, 4.0, 3.0> rgb <0, 0, 1>*25/2 fade_distance 1 fade_power 2 }

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor } scale <8, 8, 1> rotate <90, 0, 0>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // post
  texture { T_grey } scale <0.35, 0.35, 1> rotate <90, 0, 0> translate <0, 1, 0>
}
sphere { <1.6, 0.6, -0.8>, 0.6 texture { T_grey } }  // ball
