// scenes/whitted.json for POV-Ray 3.7, term for term, so that `prism-bench
// povray` times the same image in both renderers. POV-Ray is left-handed (z
// into the screen): every z is negated, which shows the same picture. prism's
// local model is POV-Ray's with diffuse 1 and a phong highlight: ambient
// ka*tex*A, diffuse kd*tex*(N.L)*I, highlight ks*(R.V)^n*I, no distance
// fall-off; reflect and transmit add the mirrored and refracted rays' colours.
// Depth and weight cut-off come from the command line
// (Declare=MaxDepth=8 Declare=MinWeight=0.0039), as prism's --max-depth and
// --min-weight: POV-Ray counts the primary ray as level 1.
#version 3.7;

#ifndef (MaxDepth) #declare MaxDepth = 8; #end
#ifndef (MinWeight) #declare MinWeight = 1 / 255; #end

global_settings {
  assumed_gamma 1.0
  max_trace_level MaxDepth + 1
  adc_bailout MinWeight
  ambient_light rgb <0.15, 0.15, 0.15>  // render.ambient
}

camera {
  perspective
  location <0, 2.0, -6.5>
  look_at <0, 0.8, 0>
  up y
  right x * image_width / image_height
  // prism's fov is vertical (40 degrees); POV-Ray's angle is horizontal
  angle 2 * degrees(atan(tan(radians(20)) * image_width / image_height))
}

background { rgb <0.45, 0.65, 0.95> }

light_source { <-4, 7, -6> color rgb 0.7 * <1, 1, 1> }
light_source { <6, 9, -2> color rgb 0.5 * <1, 0.95, 0.9> }

// checker: diffuse 0.9 x the texture, ambient 1 x the texture (the default),
// specular 0.1 ^16. prism's plane coordinates at y = 0 are (z, x), so its cells
// are POV-Ray's checker cells; negating z swaps their parity, hence the colours
// in the other order. The pattern is moved up half a cell so that the plane
// lies inside one layer of cubes.
plane {
  y, 0
  pigment {
    checker color rgb 0.9 * <1.0, 0.9, 0.1>, color rgb 0.9 * <1.0, 0.1, 0.05>
    translate <0, -0.5, 0>
  }
  finish { ambient 1 / 0.9 diffuse 1 phong 0.1 phong_size 16 }
}

// mirror: ambient 0.1, diffuse (0.1, 0.1, 0.12), specular 0.9 ^200, reflect 0.8
sphere {
  <1.1, 1.1, 1.5>, 1.1
  pigment { color rgb <0.1, 0.1, 0.12> }
  finish { ambient rgb <1, 1, 0.1 / 0.12> diffuse 1 phong 0.9 phong_size 200 reflection 0.8 }
}

// glass: ambient 0, diffuse 0.02, specular 0.9 ^300, reflect 0.1, transmit 0.9,
// ior 1.5. POV-Ray scales a transmitting surface's diffuse by 1 - transmit, so
// the pigment is 0.02 / 0.1.
sphere {
  <-0.7, 0.9, -0.8>, 0.9
  pigment { color rgbt <0.2, 0.2, 0.2, 0.9> }
  finish { ambient 0 diffuse 1 phong 0.9 phong_size 300 reflection 0.1 }
  interior { ior 1.5 }
}
