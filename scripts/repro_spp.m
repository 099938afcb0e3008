## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_spp (@var{material})
## Step of `make reproduce` (run by repro_step, which writes @var{R} to
## RESULTS/spp/MATERIAL.json), error against run time for rendering: the
## measured data rendered with fewer samples per pixel (SPP_STUDY), render
## time and PSNR against the full render.  @var{R}: @code{reference_spp},
## @code{reference_time}, @code{spp}, @code{time}, @code{psnr} (vectors).
## @end deftypefn
function R = repro_spp (material)
  c = repro_config ();
  b = merl_read (repro_files ("merl", c.data_dir, material));
  ref = exrread ([repro_files("measured", c.results, material) ".exr"]);
  mj = jsondecode (fileread (repro_files ("render_measured", c.results, material)));
  scene = repro_scene (c);
  R = struct ("material", material, "reference_spp", scene.spp,
              "reference_time", mj.info.time_total, "spp", c.spp_study,
              "time", zeros (size (c.spp_study)), "psnr", zeros (size (c.spp_study)));
  for i = 1:numel (c.spp_study)
    scene.spp = c.spp_study(i);
    scene.seed = 1000 + i;        # other samples than the reference's
    [img, info] = rt_render (scene, b, "progress", false);
    R.time(i) = info.time_total;
    R.psnr(i) = img_psnr (ref, img);
    printf ("reproduce: [%s] %3d spp: %.2f s, PSNR %.2f dB against %d spp\n", material,
            c.spp_study(i), R.time(i), R.psnr(i), R.reference_spp);
    fflush (stdout);
  endfor
endfunction
