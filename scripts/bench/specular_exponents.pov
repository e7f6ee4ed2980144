// POV-Ray 3.7 twin of scenes/specular_exponents.ron (six identical spheres, Phong
// exponents 0.5 to 500 from left to right, one directional light), for
// scripts/bench_povray.sh. raylab's right-handed coordinates are mirrored in z for
// POV-Ray's left-handed ones; diffuse and specular map to finish diffuse/phong (no
// ambient light in the scene: ambient 0); assumed_gamma 2.2 writes the colours as
// computed. max_depth 0: camera rays only (max_trace_level 1).
global_settings { assumed_gamma 2.2 max_trace_level 1 ambient_light rgb <0, 0, 0> }
background { rgb <0, 0, 0> }
camera {
  perspective
  location <0.0, 0.0, -14.0>
  look_at <0.0, 0.0, 0.0>
  right x*800/240
  angle 50.203  // horizontal; raylab's vertical fov 16 at 10:3
}
#macro Mat(N)
  pigment { rgb <0.1, 0.1, 0.3> } finish { ambient 0 diffuse 1 phong 0.8 phong_size N }
#end
light_source { <0.5, 0.6, -1.0>*1000 rgb <1, 1, 1> parallel point_at <0, 0, 0> }

sphere { <-5, 0, 0>, 0.85 texture { Mat(0.5) } }
sphere { <-3, 0, 0>, 0.85 texture { Mat(1) } }
sphere { <-1, 0, 0>, 0.85 texture { Mat(2) } }
sphere { <1, 0, 0>, 0.85 texture { Mat(10) } }
sphere { <3, 0, 0>, 0.85 texture { Mat(50) } }
sphere { <5, 0, 0>, 0.85 texture { Mat(500) } }
