## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_spp (@var{material})
## Step of `make reproduce` (run by repro_step, which writes @var{R} to
## RESULTS/spp/MATERIAL.json), error against run time for rendering: the
## measured data rendered with fewer samples per pixel (SPP_STUDY), render
## time and PSNR against the full render; and under the environment light
## ENV_MAP, one ray per pixel centre, with ENV_SAMPLES light samples per
## pixel against ENV_REFERENCE of them: time, FLIP and PSNR.  @var{R}:
## @code{reference_spp}, @code{reference_time}, @code{spp}, @code{time},
## @code{psnr} (vectors), and @code{env} (@code{map}, @code{reference},
## @code{reference_time}, @code{samples}, @code{time}, @code{flip},
## @code{psnr}).
## @end deftypefn
function R = repro_spp (material)
  c = repro_config ();
  b = repro_merl (c, material);
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
  R.env = env_study (c, b, material);
endfunction

## the light samples of an environment light: FLIP and PSNR against a
## converged render, each with other samples (seeds) than the reference's
function E = env_study (c, b, material)
  s = repro_scene (c);
  e = scene_make ("sphere", "light", "environment", "map", c.env_map, "size", [1 1]);
  s.light = e.light;
  s.spp = 1;
  s.jitter = false;
  t0 = tic ();
  [~, b.sampler] = brdf_density (b);   # the density of the BRDF samples, made once
  t_density = toc (t0);
  [ref, info] = rt_render (s, b, "progress", false, "light_samples", c.env_reference);
  n = numel (c.env_samples);
  smp = {"light", "brdf", "mis"};
  E = struct ("map", s.light.name, "reference", c.env_reference,
              "reference_time", info.time_total, "density_time", t_density,
              "samples", c.env_samples, "sampling", {smp}, "by_time", zeros (3, n),
              "by_flip", zeros (3, n), "by_psnr", zeros (3, n), "by_relmse", zeros (3, n));
  for k = 1:3
    for i = 1:n
      s.seed = 1000 + i;
      [img, info] = rt_render (s, b, "progress", false, "light_samples", c.env_samples(i),
                               "sampling", smp{k});
      q = img_compare (ref, img);
      E.by_time(k,i) = info.time_total;
      E.by_flip(k,i) = q.flip;
      E.by_psnr(k,i) = q.psnr;
      E.by_relmse(k,i) = sum ((img(:) - ref(:)) .^ 2) / max (sum (ref(:) .^ 2), realmin);
      printf ("reproduce: [%s] %s, %4d light samples (%s): %.2f s, FLIP %.3f, rel. MSE %.4f against %d (mis)\n",
              material, E.map, c.env_samples(i), smp{k}, E.by_time(k,i), E.by_flip(k,i),
              E.by_relmse(k,i), E.reference);
      fflush (stdout);
    endfor
  endfor
  ## the default sampler's row, as the fields have always been
  E.time = E.by_time(3,:);
  E.flip = E.by_flip(3,:);
  E.psnr = E.by_psnr(3,:);
endfunction
