// POV-Ray 3.7 twin of scenes/glass.ron (a glass sphere and a glass lens over a checker
// of 64 cubes, a point and a directional light), for scripts/bench_povray.sh glass.
// raylab's right-handed coordinates are mirrored in z for POV-Ray's left-handed ones;
// Phong terms map to finish ambient/diffuse/phong/reflection, raylab's 1/d^2 falloff to
// fade_power 2, transmission to a transmit pigment with interior ior 1.5. Differences
// that stay: POV-Ray's transmit scales the surface's own colour by (1 - t) and lets
// shadow rays through glass (filtered), where raylab adds the surface colour in full and
// keeps Whitted's hard shadows.
// max_trace_level 7: the camera ray is level 1, so 7 gives raylab's max_depth 6 bounces (6 gave one
// bounce fewer until 2026-12-06; POV-Ray's counts: 5 allowed 4 bounces on default.pov).
global_settings { assumed_gamma 2.2 max_trace_level 7 ambient_light rgb <1, 1, 1> }
background { rgb <0.08, 0.09, 0.12> }
camera {
  perspective
  location <0.0, 4.2, -7.5>
  look_at <0.0, 0.6, 0.0>
  right x*4/3
  angle 54.09  // horizontal; raylab's vertical fov 42 at 4:3
}
#declare Ambient = <0.25, 0.25, 0.25>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_light = texture { Mat(<0.18,0.18,0.17>, <0.8,0.78,0.72>, <0.1,0.1,0.1>, 10, 0) }
#declare T_dark  = texture { Mat(<0.05,0.06,0.1>, <0.15,0.2,0.45>, <0.1,0.1,0.1>, 10, 0) }
#declare T_red   = texture { Mat(<0.15,0.02,0.02>, <0.75,0.1,0.08>, <0.5,0.5,0.5>, 60, 0) }
#declare T_glass = texture {
  pigment { rgbt <0.02, 0.02, 0.02, 0.935> }
  finish { ambient 0 diffuse 1 phong 0.8 phong_size 300 reflection { 0.06 } }
}
#declare I_glass = interior { ior 1.5 }
light_source { <-3.0, 7.0, -5.0> rgb <1.0, 0.97, 0.92>*30 fade_distance 1 fade_power 2 }
light_source { <-0.4, 1.0, -0.3>*1000 rgb <0.35, 0.38, 0.45> parallel point_at <0, 0, 0> }

box { <-4.0, -0.2, 3.0>, <-3.0, 0.0, 4.0> texture { T_light } }
box { <-4.0, -0.2, 2.0>, <-3.0, 0.0, 3.0> texture { T_dark } }
box { <-4.0, -0.2, 1.0>, <-3.0, 0.0, 2.0> texture { T_light } }
box { <-4.0, -0.2, -0.0>, <-3.0, 0.0, 1.0> texture { T_dark } }
box { <-4.0, -0.2, -1.0>, <-3.0, 0.0, -0.0> texture { T_light } }
box { <-4.0, -0.2, -2.0>, <-3.0, 0.0, -1.0> texture { T_dark } }
box { <-4.0, -0.2, -3.0>, <-3.0, 0.0, -2.0> texture { T_light } }
box { <-4.0, -0.2, -4.0>, <-3.0, 0.0, -3.0> texture { T_dark } }
box { <-3.0, -0.2, 3.0>, <-2.0, 0.0, 4.0> texture { T_dark } }
box { <-3.0, -0.2, 2.0>, <-2.0, 0.0, 3.0> texture { T_light } }
box { <-3.0, -0.2, 1.0>, <-2.0, 0.0, 2.0> texture { T_dark } }
box { <-3.0, -0.2, -0.0>, <-2.0, 0.0, 1.0> texture { T_light } }
box { <-3.0, -0.2, -1.0>, <-2.0, 0.0, -0.0> texture { T_dark } }
box { <-3.0, -0.2, -2.0>, <-2.0, 0.0, -1.0> texture { T_light } }
box { <-3.0, -0.2, -3.0>, <-2.0, 0.0, -2.0> texture { T_dark } }
box { <-3.0, -0.2, -4.0>, <-2.0, 0.0, -3.0> texture { T_light } }
box { <-2.0, -0.2, 3.0>, <-1.0, 0.0, 4.0> texture { T_light } }
box { <-2.0, -0.2, 2.0>, <-1.0, 0.0, 3.0> texture { T_dark } }
box { <-2.0, -0.2, 1.0>, <-1.0, 0.0, 2.0> texture { T_light } }
box { <-2.0, -0.2, -0.0>, <-1.0, 0.0, 1.0> texture { T_dark } }
box { <-2.0, -0.2, -1.0>, <-1.0, 0.0, -0.0> texture { T_light } }
box { <-2.0, -0.2, -2.0>, <-1.0, 0.0, -1.0> texture { T_dark } }
box { <-2.0, -0.2, -3.0>, <-1.0, 0.0, -2.0> texture { T_light } }
box { <-2.0, -0.2, -4.0>, <-1.0, 0.0, -3.0> texture { T_dark } }
box { <-1.0, -0.2, 3.0>, <0.0, 0.0, 4.0> texture { T_dark } }
box { <-1.0, -0.2, 2.0>, <0.0, 0.0, 3.0> texture { T_light } }
box { <-1.0, -0.2, 1.0>, <0.0, 0.0, 2.0> texture { T_dark } }
box { <-1.0, -0.2, -0.0>, <0.0, 0.0, 1.0> texture { T_light } }
box { <-1.0, -0.2, -1.0>, <0.0, 0.0, -0.0> texture { T_dark } }
box { <-1.0, -0.2, -2.0>, <0.0, 0.0, -1.0> texture { T_light } }
box { <-1.0, -0.2, -3.0>, <0.0, 0.0, -2.0> texture { T_dark } }
box { <-1.0, -0.2, -4.0>, <0.0, 0.0, -3.0> texture { T_light } }
box { <0.0, -0.2, 3.0>, <1.0, 0.0, 4.0> texture { T_light } }
box { <0.0, -0.2, 2.0>, <1.0, 0.0, 3.0> texture { T_dark } }
box { <0.0, -0.2, 1.0>, <1.0, 0.0, 2.0> texture { T_light } }
box { <0.0, -0.2, -0.0>, <1.0, 0.0, 1.0> texture { T_dark } }
box { <0.0, -0.2, -1.0>, <1.0, 0.0, -0.0> texture { T_light } }
box { <0.0, -0.2, -2.0>, <1.0, 0.0, -1.0> texture { T_dark } }
box { <0.0, -0.2, -3.0>, <1.0, 0.0, -2.0> texture { T_light } }
box { <0.0, -0.2, -4.0>, <1.0, 0.0, -3.0> texture { T_dark } }
box { <1.0, -0.2, 3.0>, <2.0, 0.0, 4.0> texture { T_dark } }
box { <1.0, -0.2, 2.0>, <2.0, 0.0, 3.0> texture { T_light } }
box { <1.0, -0.2, 1.0>, <2.0, 0.0, 2.0> texture { T_dark } }
box { <1.0, -0.2, -0.0>, <2.0, 0.0, 1.0> texture { T_light } }
box { <1.0, -0.2, -1.0>, <2.0, 0.0, -0.0> texture { T_dark } }
box { <1.0, -0.2, -2.0>, <2.0, 0.0, -1.0> texture { T_light } }
box { <1.0, -0.2, -3.0>, <2.0, 0.0, -2.0> texture { T_dark } }
box { <1.0, -0.2, -4.0>, <2.0, 0.0, -3.0> texture { T_light } }
box { <2.0, -0.2, 3.0>, <3.0, 0.0, 4.0> texture { T_light } }
box { <2.0, -0.2, 2.0>, <3.0, 0.0, 3.0> texture { T_dark } }
box { <2.0, -0.2, 1.0>, <3.0, 0.0, 2.0> texture { T_light } }
box { <2.0, -0.2, -0.0>, <3.0, 0.0, 1.0> texture { T_dark } }
box { <2.0, -0.2, -1.0>, <3.0, 0.0, -0.0> texture { T_light } }
box { <2.0, -0.2, -2.0>, <3.0, 0.0, -1.0> texture { T_dark } }
box { <2.0, -0.2, -3.0>, <3.0, 0.0, -2.0> texture { T_light } }
box { <2.0, -0.2, -4.0>, <3.0, 0.0, -3.0> texture { T_dark } }
box { <3.0, -0.2, 3.0>, <4.0, 0.0, 4.0> texture { T_dark } }
box { <3.0, -0.2, 2.0>, <4.0, 0.0, 3.0> texture { T_light } }
box { <3.0, -0.2, 1.0>, <4.0, 0.0, 2.0> texture { T_dark } }
box { <3.0, -0.2, -0.0>, <4.0, 0.0, 1.0> texture { T_light } }
box { <3.0, -0.2, -1.0>, <4.0, 0.0, -0.0> texture { T_dark } }
box { <3.0, -0.2, -2.0>, <4.0, 0.0, -1.0> texture { T_light } }
box { <3.0, -0.2, -3.0>, <4.0, 0.0, -2.0> texture { T_dark } }
box { <3.0, -0.2, -4.0>, <4.0, 0.0, -3.0> texture { T_light } }

sphere { <-1.1, 1.0, -0.4>, 1 texture { T_glass } interior { I_glass } }
intersection {  // lens
  sphere { <0, 0, 0.8>, 1 }
  sphere { <0, 0, -0.8>, 1 }
  texture { T_glass } interior { I_glass }
  scale 1.1 rotate <0, 20, 0> translate <1.5, 1.3, -1.2>
}
sphere { <1.9, 0.5, 1.6>, 0.5 texture { T_red } }
