// POV-Ray 3.7 twin of scenes/mirror_cap.ron (a red sphere reflected in the mirror top cap
// of a short, wide cylinder on a floor, one point light), for scripts/bench_povray.sh.
// raylab's right-handed coordinates are mirrored in z for POV-Ray's left-handed ones
// (rotations about x turn the other way); Phong terms map to finish
// ambient/diffuse/phong/reflection, raylab's 1/d^2 falloff to fade_power 2 (POV-Ray
// fades by 2 / (1 + d^2), so intensities are halved); assumed_gamma 2.2 writes the
// colours as computed.
global_settings { assumed_gamma 2.2 max_trace_level 4 ambient_light rgb <1, 1, 1> }
background { rgb <0.15, 0.2, 0.3> }
camera {
  perspective
  location <0.0, 4.5, -5.0>
  look_at <0.0, 0.4, 0.0>
  right x*4/3
  angle 51.774  // horizontal; raylab's vertical fov 40 at 4:3
}
#declare Ambient = <0.2, 0.2, 0.2>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor  = texture { Mat(<0.1,0.1,0.1>, <0.45,0.45,0.4>, <0,0,0>, 1, 0) }
#declare T_mirror = texture { Mat(<0,0,0>, <0.05,0.05,0.05>, <0.5,0.5,0.5>, 200, 0.9) }
#declare T_red    = texture { Mat(<0.2,0.02,0.02>, <0.8,0.1,0.1>, <0.5,0.5,0.5>, 50, 0) }
light_source { <2.0, 6.0, -4.0> rgb <1, 1, 1>*50/2 fade_distance 1 fade_power 2 }

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor } scale <8, 8, 1> rotate <90, 0, 0>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // mirror drum
  texture { T_mirror } scale <1.6, 1.6, 0.25> rotate <90, 0, 0> translate <0, 0.25, -0.6>
}
sphere { <0.0, 1.3, 1.9>, 0.7 texture { T_red } }  // red ball
