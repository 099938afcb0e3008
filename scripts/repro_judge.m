## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_judge (@var{material})
## Held-out step of `make reproduce` and `make database` (run by repro_step,
## which writes @var{R} to RESULTS/judge/MATERIAL.json): every fit of
## repro_fits (each method of METHODS, each lobe count of LOBES, and in
## make database the published fit) judged in light it was not made for.
## For each light of JUDGE the pipeline's scene (its geometry, camera and
## size, JUDGE_SPP samples per pixel) is lit by that light (a light probe
## with JUDGE_SAMPLES light samples per pixel sample, or a directional
## light), the measured data rendered there by rt_render, and every fit
## rendered from that render's cache (the same samples, only the BRDF
## evaluated again) and compared with it by img_compare.  The renders under
## the first light are written as RESULTS/judge/MATERIAL-measured.exr and
## MATERIAL-METHOD-K.exr, for the held-out contact sheets.  The noise floor
## of every verdict: under each light the measured data rendered a second
## time with the next seed (scene.seed + 1, the same scene otherwise) and
## compared with the first render (img_compare's FLIP): two fits whose
## held-out FLIP differs by no more than that cannot be told apart (the
## reports call them tied, repro_tie).  A deterministic render (a
## directional light without jitter) may give a floor of 0.
##
## @var{R}: @code{lights} (struct array: @code{name}, @code{label},
## @code{type}; empty with JUDGE empty), @code{time_measured},
## @code{time_noise} (the second renders of the measured data) and
## @code{time_fits} (seconds, over the lights), @code{noise_flip} (1 x
## lights: the FLIP between the two renders of the measured data) and
## @code{noise_flip_mean} (its mean over the lights, the floor of the
## verdict; NaN with JUDGE empty), and per method a struct
## array (one per lobe count of LOBES) with @code{lobes}, @code{flip},
## @code{deltae}, @code{psnr}, @code{hue} (1 x lights) and their means
## over the lights, @code{flip_mean}, @code{deltae_mean}, @code{psnr_mean},
## @code{hue_mean}: the held-out verdict (NaN with JUDGE empty).
## @end deftypefn
function R = repro_judge (material)
  c = repro_config ();
  J = c.judge;
  nl = numel (J);
  R = struct ("material", material, "lights", struct ("name", {J.name}, "label", {J.label},
                                                     "type", {J.type}),
              "time_measured", 0, "time_noise", 0, "time_fits", 0,
              "noise_flip", nan (1, nl), "noise_flip_mean", NaN);
  models = repro_fits (c, material);
  q = {"flip", "deltae", "psnr", "hue"};
  for method = fieldnames (models)'
    mth = method{1};
    for k = find (! cellfun (@isempty, models.(mth)))
      r = struct ("lobes", k);
      for f = q
        r.(f{1}) = nan (1, nl);
      endfor
      for f = q
        r.([f{1} "_mean"]) = NaN;
      endfor
      R.(mth)(slot (c, mth, k)) = r;
    endfor
  endfor
  if (nl == 0)
    R.lights = {};                      # jsonencode aborts Octave on an empty struct array
    return;
  endif
  b = repro_merl (c, material);
  [~, b.sampler] = brdf_density (b);   # the data's own table: the same for every fit
  d = fileparts (repro_files ("judge_measured", c.results, material));
  repro_mkdir (d);
  for l = 1:nl
    scene = judge_scene (c, J(l));
    printf (["reproduce: [%s] held-out light %s: the measured data (rt_render, %d x %d, %d spp), " ...
             "twice (seeds %d and %d: the noise floor)\n"],
            material, J(l).label, scene.width, scene.height, scene.spp, scene.seed, scene.seed + 1);
    fflush (stdout);
    t0 = tic ();
    [ref, ~, cache] = rt_render (scene, b, "progress", false);
    R.time_measured += toc (t0);
    if (l == 1)
      exrwrite ([repro_files("judge_measured", c.results, material) ".exr"], ref);
    endif
    t0 = tic ();
    R.noise_flip(l) = noise_floor (scene, b, ref);
    R.time_noise += toc (t0);
    t0 = tic ();
    done = {};
    for method = fieldnames (models)'
      mth = method{1};
      for k = find (! cellfun (@isempty, models.(mth)))
        img = rt_render (scene, models.(mth){k}, "progress", false, "cache", cache);
        if (l == 1)
          exrwrite ([repro_files("judge_render", c.results, material, mth, k) ".exr"], img);
        endif
        done(end+1,:) = {mth, k, img};
      endfor
    endfor
    if (! isempty (done))
      s = img_compare (ref, done(:,3));   # the reference's part once
      for i = 1:rows (done)
        j = slot (c, done{i,1}, done{i,2});
        for f = q
          R.(done{i,1})(j).(f{1})(l) = s(i).(f{1});
        endfor
      endfor
    endif
    R.time_fits += toc (t0);
  endfor
  R.noise_flip_mean = mean (R.noise_flip);
  printf ("reproduce: [%s] held-out noise floor (FLIP between two renders of the measured data): %s, mean %.4g\n",
          material, mat2str (R.noise_flip, 4), R.noise_flip_mean);
  for method = fieldnames (models)'
    mth = method{1};
    for j = 1:numel (R.(mth))
      for f = q
        R.(mth)(j).([f{1} "_mean"]) = mean (R.(mth)(j).(f{1}));
      endfor
    endfor
    printf ("reproduce: [%s] %s: held-out FLIP (mean over %d lights) for %s lobe(s): %s\n", material,
            mth, nl, mat2str ([R.(mth).lobes]), mat2str ([R.(mth).flip_mean], 4));
  endfor
endfunction

## the record's index of method MTH's K-lobe fit: its place in LOBES (the
## published fit has one)
function j = slot (c, mth, k)
  j = merge (strcmp (mth, "ngan2005"), 1, find (c.lobes == k));
endfunction

## the noise floor of the verdicts under SCENE: the FLIP between REF (the
## measured data B rendered in SCENE) and B rendered again with the next
## seed, from no cache (other samples: with jitter, other places in the
## pixels and other light samples)
function f = noise_floor (scene, b, ref)
  scene.seed += 1;
  f = img_compare (ref, rt_render (scene, b, "progress", false)).flip;
endfunction

## the pipeline's scene lit by the held-out light L
function scene = judge_scene (c, L)
  if (strcmp (L.type, "environment"))
    scene = repro_scene (c, "spp", c.judge_spp, "light", "environment", "map", L.map,
                         "light_samples", c.judge_samples);
  else
    scene = repro_scene (c, "spp", c.judge_spp, "light_direction", L.direction);
  endif
endfunction
