## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {@var{sm} =} repro_summary (@var{c})
## The numbers of `make reproduce`'s report, computed once from the
## materials' records in RESULTS with the settings @var{c} (repro_config).
## @var{sm} is summary.json, and all that report.md says (repro_report
## fills the template report_reproduce from it): the data used
## (@code{data}), per material the paper's PSNR, every fit's measures by
## both renderers and under the held-out lights, its errors, times and
## traces, the render times against samples (@code{materials}), the best
## method by held-out FLIP (@code{heldout}), the models compared
## (@code{best_model}, @code{models}), the study of tables and weightings
## (@code{study}, when STUDY is on) and the settings.
## @end deftypefn
function sm = repro_summary (c)
  known = struct ("h90d2ee46", "the real MERL measurement",
                  "hd6407989", "the real MERL measurement",
                  "h7cb7830f", "a neural-network reconstruction of the MERL measurement (Neural-BRDF stand-in, not the measurement)",
                  "h54d51a41", "a neural-network reconstruction of the MERL measurement (Neural-BRDF stand-in, not the measurement)");
  sm = struct ();
  sm.data = struct ();
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    src = jsondecode (fileread (repro_files ("source", c.results, mat)));
    if (strcmp (src.kind, "merl-file"))
      tag = ["h" src.sha256(1:min (8, end))];
      what = "a MERL-format file of unknown origin";
      if (isfield (known, tag))
        what = known.(tag);
      endif
    else
      what = "the toolbox's built-in stand-in (a Cook–Torrance model with the parameters Ngan et al. 2005 published for this material, in MERL format with 3% noise and missing grazing samples), not the measurement";
    endif
    sm.data.(repro_field (mat)) = struct ("kind", src.kind, "path", src.path, "sha256", src.sha256, "what", what);
  endfor
  sm.materials = struct ();
  rec = cellfun (@(m) records (c, m), c.materials, "uniformoutput", false);
  for i = 1:numel (c.materials)
    sm.materials.(repro_field (c.materials{i})) = material (c, c.materials{i}, rec{i});
  endfor
  [sm.heldout, sm.best_model, sm.models] = verdicts (c, rec);
  scene = repro_scene (c);
  sm.settings = struct ("scene", scene.name, "width", scene.width, "height", scene.height,
                        "spp", scene.spp, "pov_antialias", c.pov_aa, "max_angle", c.max_angle,
                        "quick", c.quick, "lobes", c.lobes, "methods", {c.methods},
                        "judge_samples", c.judge_samples, "judge_spp", c.judge_spp,
                        "merl_dir", c.merl_dir, "mesh", c.mesh, "scene_name", c.scene,
                        "date", datestr (now (), "yyyy-mm-dd HH:MM"), "octave", OCTAVE_VERSION,
                        "cores", nproc ());
  sm.study = struct ();
  if (c.study)
    for i = 1:numel (c.materials)
      R = jsondecode (fileread (repro_files ("study", c.results, c.materials{i})));
      sm.study.(repro_field (c.materials{i})) = struct ("light_b", R.light_b(:)', "methods", R.methods);
    endfor
  endif
endfunction

## the records of material MAT's steps, each read once
function r = records (c, mat)
  r = struct ();
  for s = {"render_fits", "fit", "spp", "judge", "render_measured"}
    r.(s{1}) = jsondecode (fileread (repro_files (s{1}, c.results, mat)));
  endfor
endfunction

## material MAT's numbers, from its records REC
function s = material (c, mat, rec)
  R = rec.render_fits;
  F = rec.fit;
  P = rec.spp;
  J = rec.judge;
  M = rec.render_measured;
  nk = numel (c.lobes);
  s = struct ();
  s.paper_psnr = repro_paper (c, mat);
  s.renderers_psnr = [R.inplane.renderers_psnr];
  s.renderers_psnr_measured = M.renderers_psnr;
  s.fit_rel_rmse_inplane = mean (F.inplane.errors.inplane.rel_rmse, 2)';
  for m = c.methods
    for q = {"psnr", "flip", "deltae", "hue"}
      for r = {"pov", "rt"}
        f = [q{1} "_" r{1}];
        s.([q{1} "_" m{1} "_" r{1}]) = [R.(m{1}).(f)];
      endfor
    endfor
    s.(["fit_rmse_" m{1}]) = mean (F.(m{1}).errors.(repro_method (m{1}).base).rmse, 2)';
    s.(["fit_time_" m{1}]) = max (F.(m{1}).lobe_time, [], 2)';
  endfor
  for m = c.methods
    s.(["flip_" m{1} "_heldout"]) = repro_row (J.(m{1}), "flip_mean", nk);
    s.(["deltae_" m{1} "_heldout"]) = repro_row (J.(m{1}), "deltae_mean", nk);
  endfor
  s.heldout_time_measured = J.time_measured;
  s.heldout_time_fits = J.time_fits;
  ## the noise floor: two renders of the measured data under each light
  [s.heldout_noise_flip_mean, s.heldout_noise_flip, s.heldout_time_noise] = noise_of (J, numel (c.judge));
  s.render_time_measured = M.info.time_total;
  s.render_time_pov = [R.inplane.pov_time];
  s.render_time_rt = [R.inplane.rt_time];
  s.spp = P.spp(:)';
  s.spp_time = P.time(:)';
  s.spp_psnr = P.psnr(:)';
  s.env_samples = P.env.samples(:)';
  s.env_time = P.env.time(:)';
  s.env_flip = P.env.flip(:)';
  ## (added after the fields above, which summary.json has always had)
  s.spp_reference = P.reference_spp;
  s.spp_reference_time = P.reference_time;
  s.env_psnr = P.env.psnr(:)';
  s.env_map = P.env.map;
  s.env_reference = P.env.reference;
  s.env_reference_time = P.env.reference_time;
  ## each sampling's row (light, brdf, mis), against the mis reference
  s.env_sampling = cellstr (P.env.sampling)(:)';
  s.env_by_time = P.env.by_time;
  s.env_by_flip = P.env.by_flip;
  s.env_by_psnr = P.env.by_psnr;
  s.env_by_relmse = P.env.by_relmse;
  s.env_density_time = P.env.density_time;
  s.material_bytes = M.info.material_bytes;
  ## every method's errors on every table (means over R, G, B) per lobe count
  tables = unique (cellfun (@(m) repro_method (m).base, c.methods, "uniformoutput", false), "stable");
  s.errors = struct ();
  for m = c.methods
    e = struct ();
    for t = unique ([{"inplane"}, tables], "stable")
      for q = {"rmse", "rel_rmse", "log_rmse", "cos_rmse"}
        e.(t{1}).(q{1}) = arrayfun (@(k) mean (F.(m{1}).errors.(t{1}).(q{1})(k,:)), c.lobes);
      endfor
    endfor
    e.time = arrayfun (@(k) max (F.(m{1}).lobe_time(k,:)), c.lobes);
    s.errors.(m{1}) = e;
  endfor
  ## the in-plane fit's error against run time, per channel: the rmse of the
  ## best parameters so far, growing from 1 to the most lobes
  s.trace = struct ("final", {}, "t10", {}, "t1", {}, "total", {});
  for ch = 1:3
    T = F.inplane.trace;                # K x 2 per channel, as jsondecode returns them
    if (iscell (T))
      T = T{ch};
    else
      T = reshape (T(ch,:,:), [], 2);
    endif
    fin = T(end,2);
    s.trace(ch) = struct ("final", fin, "t10", T(find (T(:,2) <= 1.1 * fin, 1), 1),
                          "t1", T(find (T(:,2) <= 1.01 * fin, 1), 1), "total", T(end,1));
  endfor
  ## the held-out FLIP of every fit under each light (lobes x lights)
  s.heldout_lights = struct ();
  for m = c.methods
    s.heldout_lights.(m{1}) = zeros (nk, numel (c.judge));
    for j = 1:min (nk, numel (J.(m{1})))
      s.heldout_lights.(m{1})(j,:) = J.(m{1})(j).flip(:)';
    endfor
  endfor
endfunction

## per material and lobe count, the method with the lowest held-out FLIP
## and the methods tied with it (within the material's noise floor,
## repro_tie), and the models compared on the verdicts' FLIP (held out, or
## in-sample without held-out lights): the best of each model over the
## methods (repro_models) and the best model, with the models tied with it
## (REC: each material's records)
function [H, S, MD] = verdicts (c, rec)
  mats = c.materials;
  nk = numel (c.lobes);
  H = struct ("lights", {{c.judge.label}}, "best_method", struct ());
  held = ! isempty (c.judge);
  F = struct ();
  for m = c.methods
    F.(m{1}) = nan (numel (mats), nk);
  endfor
  floor = nan (numel (mats), 1);
  for i = 1:numel (mats)
    J = rec{i}.judge;
    R = rec{i}.render_fits;
    floor(i) = noise_of (J, numel (c.judge));
    best = repmat ({""}, 1, nk);
    bf = Inf (1, nk);
    for m = c.methods
      if (held)
        F.(m{1})(i,:) = repro_row (J.(m{1}), "flip_mean", nk);
        for j = 1:nk
          if (J.(m{1})(j).flip_mean < bf(j))
            bf(j) = J.(m{1})(j).flip_mean;
            best{j} = m{1};
          endif
        endfor
      else
        F.(m{1})(i,:) = [R.(m{1}).flip_pov];
      endif
    endfor
    if (held)
      tied = best;
      for m = c.methods
        tie = repro_tie (F.(m{1})(i,:), bf, floor(i)) & ! strcmp (best, m{1});
        tied(tie) = strcat (tied(tie), {", "}, m(1));
      endfor
      H.best_method.(repro_field (mats{i})) = struct ("method", {best}, "flip", bf, "tied", {tied},
                                                      "noise_flip", floor(i));
    endif
  endfor
  [M, B] = repro_models (c, F, floor);
  S = struct ();
  for i = 1:numel (mats)
    S.(repro_field (mats{i})) = struct ("model", {B.model(i,:)}, "method", {B.method(i,:)}, "flip", B.flip(i,:),
                                        "tied", {B.tied(i,:)});
  endfor
  MD = struct ("model", {M.model}, "flip", {M.flip}, "method", {M.method});
endfunction

## the noise floor of judge record J (repro_judge) under NL lights: its mean
## F over the lights, per light FL (1 x NL) and its time T; NaN where the
## record holds none (JUDGE empty: null; a record older than the floor)
function [f, fl, t] = noise_of (J, nl)
  f = NaN;
  fl = nan (1, nl);
  t = NaN;
  if (isfield (J, "noise_flip") && isnumeric (J.noise_flip) && numel (J.noise_flip) == nl)
    fl = J.noise_flip(:)';
    f = mean (fl);
    t = J.time_noise;
  endif
endfunction
