// POV-Ray 3.7 twin of scenes/shapes.ron (the course's five unit shapes at odd angles on a
// ground square, a point and a directional light), for scripts/bench_povray.sh.
// raylab's right-handed coordinates are mirrored in z for POV-Ray's left-handed ones
// (rotations about x and y turn the other way, the cone opens towards -z); Phong terms
// map to finish ambient/diffuse/phong, raylab's 1/d^2 falloff to fade_power 2 (POV-Ray
// fades by 2 / (1 + d^2), so intensities are halved); assumed_gamma 2.2 writes the
// colours as computed. max_depth 2 and no mirrors: camera and shadow rays only.
global_settings { assumed_gamma 2.2 max_trace_level 3 ambient_light rgb <1, 1, 1> }
background { rgb <0.03, 0.03, 0.05> }
camera {
  perspective
  location <0.0, 3.0, -9.0>
  look_at <0.0, 0.6, 0.0>
  right x*1.6
  angle 60.429  // horizontal; raylab's vertical fov 40 at 16:10
}
#declare Ambient = <0.2, 0.2, 0.2>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_ground = texture { Mat(<0.1,0.1,0.1>, <0.5,0.5,0.5>, <0,0,0>, 1, 0) }
#declare T_clay   = texture { Mat(<0.15,0.1,0.08>, <0.8,0.55,0.4>, <0.4,0.4,0.4>, 30, 0) }
#declare T_teal   = texture { Mat(<0.05,0.15,0.15>, <0.2,0.65,0.65>, <0.5,0.5,0.5>, 50, 0) }
light_source { <-5.0, 6.0, -6.0> rgb <1.0, 0.95, 0.9>*60/2 fade_distance 1 fade_power 2 }
light_source { <-1.0, 0.5, -0.6>*1000 rgb <0.3, 0.35, 0.5> parallel point_at <0, 0, 0> }

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // ground
  texture { T_ground } scale <12, 12, 1> rotate <90, 0, 0>
}
sphere { 0, 1  // sphere
  texture { T_clay } scale <0.9, 0.6, 0.75> rotate <-20, -35, 10> translate <-3.2, 0.9, 0.0>
}
box { -1, 1  // cube
  texture { T_teal } scale 0.6 rotate <-35, -40, 15> translate <-1.1, 0.9, 0.3>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // cylinder
  texture { T_clay } scale <0.5, 0.5, 0.8> rotate <60, -25, 0> translate <0.9, 0.9, -0.2>
}
cone { <0, 0, 0>, 0, <0, 0, -1>, 1  // cone
  texture { T_teal } scale <0.7, 0.7, 1.3> rotate <-110, -20, -15> translate <2.8, 1.5, 0.0>
}
polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // tilted square
  texture { T_clay } rotate <-10, -30, 45> translate <0.0, 1.6, 3.0>
}
