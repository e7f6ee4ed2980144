// POV-Ray 3.7 twin of scenes/spotlights.ron (a sphere and a cube on a floor under four
// spot lights of 9 to 80 degrees), for scripts/bench_povray.sh. raylab's right-handed
// coordinates are mirrored in z for POV-Ray's left-handed ones (rotations about y turn
// the other way); Phong terms map to finish ambient/diffuse/phong, raylab's 1/d^2 falloff
// to fade_power 2 (POV-Ray fades by 2 / (1 + d^2), so intensities are halved);
// assumed_gamma 2.2 writes the colours as computed. What differs: raylab's spot has a
// hard edge at its half-angle and no fall-off inside; POV-Ray's spotlight with radius =
// falloff = that angle has the same edge, and tightness 0 keeps it flat inside.
global_settings { assumed_gamma 2.2 max_trace_level 2 ambient_light rgb <1, 1, 1> }
background { rgb <0, 0, 0> }
camera {
  perspective
  location <0.0, 5.0, -9.0>
  look_at <0.0, 0.3, 0.0>
  right x*4/3
  angle 54.208  // horizontal; raylab's vertical fov 42 at 4:3
}
#declare Ambient = <0.1, 0.1, 0.1>;
#macro Mat(A, D, S, N, M)
  pigment { rgb D } finish { ambient A*Ambient/D diffuse 1 phong vlength(S)/sqrt(3) phong_size N reflection { M } }
#end
#declare T_floor = texture { Mat(<0.05,0.05,0.05>, <0.7,0.7,0.7>, <0.2,0.2,0.2>, 10, 0) }
#declare T_white = texture { Mat(<0.05,0.05,0.05>, <0.8,0.8,0.8>, <0.5,0.5,0.5>, 40, 0) }
#macro Spot(P, D, A, C)
  light_source { P rgb C fade_distance 1 fade_power 2
    spotlight radius A falloff A tightness 0 point_at P + D }
#end
Spot(<-3.5, 6.0, -1.0>, <0.0, -1.0, 0.0>, 30, <0.3, 0.45, 1.0>*40/2)   // wide, straight down, blue
Spot(<-2.0, 4.0, -3.0>, <1.05, -1.0, 1.15>, 9, <1.0, 0.7, 0.3>*45/2)  // narrow, slanted
Spot(<5.0, 2.0, -2.0>, <-1.0, -0.35, 0.2>, 18, <0.4, 1.0, 0.5>*30/2)  // from the right, low
Spot(<0.0, 3.0, 6.0>, <0.0, -0.6, -1.0>, 80, <0.6, 0.3, 0.6>*25/2)    // very wide, from behind

polygon { 5, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0>, <-1, -1, 0>  // floor
  texture { T_floor } scale <10, 10, 1> rotate <90, 0, 0>
}
sphere { <-0.6, 1.0, -0.2>, 1 texture { T_white } }  // sphere
box { -1, 1  // cube
  texture { T_white } scale 0.7 rotate <0, -20, 0> translate <1.4, 0.7, 1.2>
}
