## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_render_measured (@var{material})
## Render step of `make reproduce` and `make database` (run by repro_step,
## which writes @var{R} to RESULTS/render/MATERIAL-measured.json): the scene
## rendered with the measured data DATA_DIR/MATERIAL.binary by the Octave
## raytracer, RESULTS/render/MATERIAL-measured.exr and .png, and by POV-Ray
## (the fits' renderer, with their anti-aliasing),
## RESULTS/render/MATERIAL-measured-pov.exr.  @var{R}: @code{scene},
## @code{width}, @code{height}, @code{spp}, @code{info} (rt_render's times
## and memory), @code{pov_time}, @code{pov_scene_bytes} and
## @code{renderers_psnr} (the two measured renders against each other).
## @end deftypefn
function R = repro_render_measured (material)
  c = repro_config ();
  b = repro_merl (c, material);
  scene = repro_scene (c);
  printf ("reproduce: [%s] rendering the measured data (rt_render, %d x %d, %d spp)\n",
          material, scene.width, scene.height, scene.spp);
  fflush (stdout);
  [img, info, cache] = rt_render (scene, b, "progress", true);
  repro_trace (scene, cache);         # the fits' renders shade from this trace
  base = repro_files ("measured", c.results, material);
  repro_mkdir (fileparts (base));
  exrwrite ([base ".exr"], img);
  img_write_png ([base ".png"], img, "auto");
  ## the measured data through POV-Ray as well, with the fits' samples: the
  ## fits' POV-Ray renders are compared with it, so that both sides of each
  ## PSNR see the same sample positions (on a mesh whose triangles are
  ## smaller than a pixel, different positions alone cost much of the PSNR:
  ## README, "Measurements behind the design")
  printf ("reproduce: [%s] rendering the measured data (POV-Ray, anti-aliasing %d)\n",
          material, c.pov_aa);
  fflush (stdout);
  [pimg, pinfo] = pov_render (scene, b, "antialias", c.pov_aa, "threads", c.pov_threads);
  exrwrite ([repro_files("measured_pov", c.results, material) ".exr"], pimg);
  R = struct ("material", material, "scene", scene.name, "width", scene.width,
              "height", scene.height, "spp", scene.spp, "info", clean_info (info),
              "pov_time", pinfo.time + pinfo.write_time, "pov_scene_bytes", pinfo.bytes,
              "renderers_psnr", img_psnr (img, pimg));
  printf ("reproduce: [%s] measured render: %.1f s (rt_render), %.1f s (POV-Ray); the two agree to %.1f dB\n",
          material, info.time_total, R.pov_time, R.renderers_psnr);
endfunction

function s = clean_info (info)
  ## numbers and strings only, for JSON
  s = struct ();
  for f = fieldnames (info)'
    v = info.(f{1});
    if (isnumeric (v) || islogical (v) || ischar (v) || isstruct (v))
      s.(f{1}) = v;
    endif
  endfor
endfunction
