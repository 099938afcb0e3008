## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_render_measured (@var{material})
## Render step of `make reproduce` and `make database` (run by repro_step,
## which writes @var{R} to RESULTS/render/MATERIAL-measured.json): the scene
## rendered with the measured data DATA_DIR/MATERIAL.binary by the Octave
## raytracer, RESULTS/render/MATERIAL-measured.exr and .png.  @var{R}:
## @code{scene}, @code{width}, @code{height}, @code{spp} and @code{info}
## (rt_render's times and memory).
## @end deftypefn
function R = repro_render_measured (material)
  c = repro_config ();
  b = merl_read (fullfile (c.data_dir, [material ".binary"]));
  scene = repro_scene (c);
  printf ("reproduce: [%s] rendering the measured data (rt_render, %d x %d, %d spp)\n",
          material, scene.width, scene.height, scene.spp);
  fflush (stdout);
  [img, info] = rt_render (scene, b, "progress", true);
  outdir = fullfile (c.results, "render");
  if (! isfolder (outdir))
    mkdir (outdir);
  endif
  exrwrite (fullfile (outdir, [material "-measured.exr"]), img);
  img_write_png (fullfile (outdir, [material "-measured.png"]), img, "auto");
  R = struct ("material", material, "scene", scene.name, "width", scene.width,
              "height", scene.height, "spp", scene.spp, "info", clean_info (info));
  printf ("reproduce: [%s] measured render: %.1f s\n", material, info.time_total);
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
