## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{R} =} repro_render_fits (@var{material})
## Render step of `make reproduce` and `make database` (run by repro_step,
## which writes @var{R} to RESULTS/render/MATERIAL-fits.json): every fitted
## model (each method of METHODS, each lobe count of LOBES) rendered with
## POV-Ray in the same scene as the measured data, and with the Octave
## raytracer too (same samples as the measured render; it evaluates the
## model per sample, where POV-Ray interpolates tables of at most 256
## entries per map, a POV-Ray limit, too few for highlights with exponents
## above about 1e4).  PSNR of each
## against the measured data rendered by the same renderer with the same
## samples (RESULTS/render/MATERIAL-measured-pov.exr for POV-Ray,
## MATERIAL-measured.exr for rt_render; peak = that image's maximum), so
## that sampling noise cancels and the PSNR measures the model; beside it
## HDR-FLIP, the mean CIEDE2000 and the hue statistic (img_compare).
## Writes RESULTS/render/MATERIAL-METHOD-K.exr and .png.
##
## In make database, the material's published fit (PUBLISHED, read by
## lafortune_ngan) is rendered too, as the method @code{ngan2005} with one
## lobe.
##
## @var{R}: @code{antialias} and per method a struct array (one per lobe
## count) with @code{lobes}, @code{psnr_pov}, @code{psnr_rt},
## @code{flip_pov}, @code{flip_rt}, @code{deltae_pov}, @code{deltae_rt},
## @code{hue_pov}, @code{hue_rt}, @code{renderers_psnr}, @code{pov_time}, @code{pov_scene_bytes},
## @code{rt_time}.
## @end deftypefn
function R = repro_render_fits (material)
  c = repro_config ();
  scene = repro_scene (c);
  ref = exrread ([repro_files("measured", c.results, material) ".exr"]);         # rt_render
  refpov = exrread ([repro_files("measured_pov", c.results, material) ".exr"]);  # POV-Ray
  R = struct ("material", material, "antialias", c.pov_aa);
  models = repro_fits (c, material);   # METHODS x LOBES, and the published fit
  ## rt_render's trace: the measured render's, when that ran in this process
  ## (repro_material), else made by the first fit's render; the rest shade
  cache = repro_trace (scene);
  done = {};          # the renders, compared at the end: each reference's part once
  for method = fieldnames (models)'
    mth = method{1};
    for k = 1:numel (models.(mth))
      if (! isempty (models.(mth){k}))
        done(end+1,:) = {mth, k, models.(mth){k}, [], [], [], []};
      endif
    endfor
  endfor
  if (! isempty (done))
    ## every fit by POV-Ray in one call: their POV-Ray runs at once
    printf ("reproduce: [%s] POV-Ray renders of %d fits\n", material, rows (done));
    fflush (stdout);
    [imgs, pinfos] = pov_render (scene, done(:,3)', "antialias", c.pov_aa, "threads", c.pov_threads);
    done(:,4) = imgs(:);
    done(:,6) = pinfos(:);
  endif
  for i = 1:rows (done)
    [mth, k, m, img] = done{i,1:4};
    base = repro_files ("fit_render", c.results, material, mth, k);
    exrwrite ([base ".exr"], img);
    img_write_png ([base ".png"], img, "auto");
    ## the same model through the Octave raytracer, with the measured
    ## render's samples
    [done{i,5}, done{i,7}, cache] = rt_render (scene, m, "progress", false, "cache", cache);
  endfor
  repro_trace (scene, []);            # the trace is not needed after this step
  if (isempty (done))
    return;
  endif
  qp = img_compare (refpov, done(:,4));
  qr = img_compare (ref, done(:,5));
  for i = 1:rows (done)
    [mth, k, ~, img, img_rt, pinfo, rinfo] = done{i,:};
    r = struct ("lobes", k, "psnr_pov", qp(i).psnr, "psnr_rt", qr(i).psnr,
                "flip_pov", qp(i).flip, "flip_rt", qr(i).flip, "deltae_pov", qp(i).deltae,
                "deltae_rt", qr(i).deltae, "hue_pov", qp(i).hue, "hue_rt", qr(i).hue,
                "renderers_psnr", img_psnr (img_rt, img), "pov_time", pinfo.time,
                "pov_scene_bytes", pinfo.bytes, "rt_time", rinfo.time_total);
    R.(mth)(merge (strcmp (mth, "ngan2005"), 1, find (c.lobes == k))) = r;
    printf ("reproduce: [%s] %s %d lobe(s): PSNR %.2f dB, FLIP %.4f, dE %.2f (POV-Ray, %.1f s); %.2f dB, FLIP %.4f, dE %.2f (rt_render, %.1f s)\n",
            material, mth, k, r.psnr_pov, r.flip_pov, r.deltae_pov, r.pov_time,
            r.psnr_rt, r.flip_rt, r.deltae_rt, r.rt_time);
  endfor
endfunction

