// POV-Ray 3.7 twin of scenes/soft_spot.ron (a sphere, an upside-down cone and a short
// mirror-topped pillar on a floor under a spot light of radius 0.4 with 16 shadow rays,
// and a small point light), for scripts/bench_povray.sh. raylab's right-handed
// coordinates are mirrored in z for POV-Ray's left-handed ones (rotations about x turn the
// other way, the cone opens towards -z); Phong terms map to finish
// ambient/diffuse/phong/reflection, raylab's 1/d^2 falloff to fade_power 2 (POV-Ray fades
// by 2 / (1 + d^2), so intensities are halved); raylab's hard-edged spot is POV-Ray's
// spotlight with radius = falloff; assumed_gamma 2.2 writes the colours as computed.
// What differs: raylab's sphere light casts its 16 shadow rays at stratified, jittered
// points of the light's disc as seen from the hit; POV-Ray's area_light here is a 4x4 grid
// on a disc of the same radius turned to face the hit (circular orient), not jittered
// and not adaptive, so it casts 16 rays too but its penumbra is banded where raylab's is
// noisy.
global_settings { assumed_gamma 2.2 max_trace_level 3 ambient_light rgb <1, 1, 1> }
background { rgb <0.02, 0.02, 0.03> }
camera {
  perspective
  location <0.0, 4.5, -8.0>
  look_at <0.0, 0.5, 0.0>
  right x*4/3
  angle 57.822  // horizontal; raylab's vertical fov 45 at 4:3
}
#declare Ambient = <0.3, 0.3, 0.3>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor = texture { Mat(<0.05,0.05,0.05>, <0.75,0.75,0.72>, <0.1,0.1,0.1>, 10, 0) }
#declare T_clay  = texture { Mat(<0.08,0.04,0.03>, <0.8,0.45,0.3>, <0.3,0.3,0.3>, 30, 0) }
#declare T_jade  = texture { Mat(<0.03,0.07,0.05>, <0.3,0.7,0.5>, <0.5,0.5,0.5>, 60, 0) }
#declare T_slate = texture { Mat(<0.04,0.04,0.06>, <0.35,0.4,0.6>, <0.2,0.2,0.2>, 20, 0.15) }
light_source {
  <0.5, 5.0, -1.5> rgb <1.0, 0.95, 0.85>*30/2 fade_distance 1 fade_power 2
  spotlight radius 40 falloff 40 point_at <0.5 - 0.1, 5.0 - 1.0, -1.5 + 0.3>
  area_light <0.8, 0, 0>, <0, 0.8, 0>, 4, 4 circular orient
}
light_source { <-5.0, 3.0, -4.0> rgb <0.4, 0.45, 0.6>*12/2 fade_distance 1 fade_power 2 }

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor } scale <8, 8, 1> rotate <90, 0, 0>
}
sphere { <-1.2, 1.6, 0.0>, 0.7 texture { T_clay } }  // ball
cone { <0, 0, 0>, 0, <0, 0, -1>, 1  // cone
  texture { T_jade } scale <0.6, 0.6, 1.4> rotate <90, 0, 0> translate <1.3, 1.4, 0.5>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 1  // pillar
  texture { T_slate } scale <0.35, 0.35, 0.4> rotate <-90, 0, 0> translate <0.2, 0.4, -1.2>
}
