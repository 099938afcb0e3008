## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_report ()
## Last step of `make reproduce`: RESULTS/report.md (our numbers beside the
## paper's, the best model of each material (MODELS, repro_models), fit
## errors and times, error against run time for fitting and rendering) and
## RESULTS/summary.json (the same numbers for machines).
## @end deftypefn
function repro_report ()
  c = repro_config ();
  known = struct ("h90d2ee46", "the real MERL measurement",
                  "hd6407989", "the real MERL measurement",
                  "h7cb7830f", "a neural-network reconstruction of the MERL measurement (Neural-BRDF stand-in, not the measurement)",
                  "h54d51a41", "a neural-network reconstruction of the MERL measurement (Neural-BRDF stand-in, not the measurement)");
  L = {};
  L{end+1} = "# lafortune: Lafortune-model fits of measured BRDFs, reproduced";
  L{end+1} = "";
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
      line = sprintf ("- **%s**: `%s` (sha256 %s…): %s.", mat, src.path, src.sha256(1:min (12, end)), what);
    else
      what = "the toolbox's built-in stand-in (a Cook–Torrance model with the parameters Ngan et al. 2005 published for this material, in MERL format with 3% noise and missing grazing samples), not the measurement";
      line = sprintf ("- **%s**: no MERL file found in `%s`: %s.", mat, c.merl_dir, what);
    endif
    L{end+1} = line;
    sm.data.(fieldname (mat)) = struct ("kind", src.kind, "path", src.path, "sha256", src.sha256, "what", what);
  endfor
  scene = repro_scene (c);
  L{end+1} = "";
  L{end+1} = sprintf (["Data used (above). Settings: scene `%s` (%s), %d x %d pixels (W x H), %d samples per " ...
                       "pixel for rt_render (stratified, jittered); the measured data and the fits rendered with POV-Ray " ...
                       "(anti-aliasing %d x %d plus the centre ray) and, as a control, with rt_render on the same samples; " ...
                       "grazing angles beyond %d degrees left out of the fits; %s run; %s, Octave %s, %d cores."],
                      scene.name, scene_desc (c), scene.width, scene.height, scene.spp, c.pov_aa, c.pov_aa,
                      c.max_angle, ifelse (c.quick, "QUICK (classroom)", "full"),
                      datestr (now (), "yyyy-mm-dd HH:MM"), OCTAVE_VERSION, nproc ());
  L{end+1} = "";
  L{end+1} = ["PSNR convention: 10 log10 (peak^2 / MSE), peak = the measured render's maximum, MSE over all pixels and channels of the linear HDR images. " ...
              "Each fit is compared with the measured data rendered by the same renderer with the same samples, so that sampling noise cancels " ...
              "(the two measured renders, rt_render and POV-Ray, agree to the dB given below the table: the noise floor of a comparison across renderers)."];
  L{end+1} = "";
  ## --- PSNR table
  L{end+1} = "## PSNR of each fit's render against the measured-data render";
  L{end+1} = "";
  L{end+1} = ["The paper rendered the Happy Buddha with pbrt; our scene differs (see settings), so compare trends, not decibels. " ...
              "These renders are in the scene's own light, the one the scene fit was made for: its scores here are in-sample. " ...
              "The verdicts are made under held-out light (below)."];
  L{end+1} = "";
  need_inplane (c);
  others = c.methods(! strcmp (c.methods, "inplane"));
  ## the tables of the fits' errors: the methods without their models
  tables = unique (cellfun (@(m) repro_method (m).base, c.methods, "uniformoutput", false), "stable");
  otables = tables(! strcmp (tables, "inplane"));
  hdr = "| material | lobes | paper | in-plane fit, POV-Ray | in-plane fit, rt_render |";
  for m = others
    hdr = [hdr sprintf(" %s fit, POV-Ray / rt_render |", repro_method (m{1}).label)];
  endfor
  L{end+1} = [hdr " rt_render vs POV-Ray (same model) |"];
  L{end+1} = ["|---|---|---|---|---|" repmat("---|", 1, numel (others)) "---|"];
  sm.materials = struct ();
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    R = jsondecode (fileread (repro_files ("render_fits", c.results, mat)));
    F = jsondecode (fileread (repro_files ("fit", c.results, mat)));
    P = jsondecode (fileread (repro_files ("spp", c.results, mat)));
    J = jsondecode (fileread (repro_files ("judge", c.results, mat)));
    M = jsondecode (fileread (repro_files ("render_measured", c.results, mat)));
    paper = repro_paper (c, mat);
    for j = 1:numel (c.lobes)
      k = c.lobes(j);
      ptxt = "-";
      if (! isnan (paper(j)))
        ptxt = sprintf ("%.2f dB", paper(j));
      endif
      row = sprintf ("| %s | %d | %s | %.2f dB | %.2f dB |", mat, k, ptxt,
                     R.inplane(j).psnr_pov, R.inplane(j).psnr_rt);
      for m = others
        row = [row sprintf(" %.2f / %.2f dB |", R.(m{1})(j).psnr_pov, R.(m{1})(j).psnr_rt)];
      endfor
      L{end+1} = [row sprintf(" %.1f dB |", R.inplane(j).renderers_psnr)];
    endfor
    s = struct ();
    s.paper_psnr = paper;
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
      s.(["flip_" m{1} "_heldout"]) = repro_row (J.(m{1}), "flip_mean", numel (c.lobes));
      s.(["deltae_" m{1} "_heldout"]) = repro_row (J.(m{1}), "deltae_mean", numel (c.lobes));
    endfor
    s.heldout_time_measured = J.time_measured;
    s.heldout_time_fits = J.time_fits;
    s.render_time_measured = M.info.time_total;
    s.render_time_pov = [R.inplane.pov_time];
    s.render_time_rt = [R.inplane.rt_time];
    s.spp = P.spp(:)';
    s.spp_time = P.time(:)';
    s.spp_psnr = P.psnr(:)';
    s.env_samples = P.env.samples(:)';
    s.env_time = P.env.time(:)';
    s.env_flip = P.env.flip(:)';
    sm.materials.(fieldname (mat)) = s;
    D.(fieldname (mat)) = struct ("F", F, "R", R, "P", P, "M", M, "J", J);
  endfor
  L{end+1} = "";
  L{end+1} = ["The measured data rendered by rt_render and by POV-Ray agree to " ...
              strjoin(cellfun (@(m) sprintf ("%.1f dB (%s)", sm.materials.(fieldname (m)).renderers_psnr_measured, m),
                               c.materials, "uniformoutput", false), ", ") ...
              ": PSNRs across renderers (the last column) cannot exceed that."];
  L{end+1} = "";
  for i = 1:numel (c.materials)
    L{end+1} = sprintf ("![measured and fitted renders, %s](figures/renders-%s.png)",
                        strrep (c.materials{i}, "-", " "), c.materials{i});
  endfor
  L{end+1} = "";
  L{end+1} = "Each fit's render has its HDR-FLIP error map (per pixel; black: no visible difference, white: the largest) in the corner, and its FLIP under its PSNR.";
  L{end+1} = "";
  L = perceptual_section (c, L, D);
  [L, sm.heldout] = heldout_section (c, L, D);
  ## --- the models: the best of each material
  [L, sm.best_model] = models_section (c, L, D);
  ## --- the study
  if (c.study)
    L = study_section (c, L);
  endif
  ## --- fits
  L{end+1} = "## Fits";
  L{end+1} = "";
  L{end+1} = ["Errors are means over R, G, B of per-channel errors; `in-plane` is the paper's table (plane of incidence), " ...
              "`hemisphere` every valid MERL bin (subsampled, weighted by solid angle), `scene` the angle pairs the scene's pixels see " ...
              "(fitted with lafortune_fit's defaults for a scene table: relative weights; its rmse is weighted by each pair's share of the image). " ...
              "Fit time is cumulative: the k-lobe fit grows from the (k-1)-lobe one."];
  L{end+1} = "";
  hdr = "| material | fit | lobes | rmse (in-plane table) | relative rmse | log rmse | cosine-weighted rmse |";
  for m = otables
    hdr = [hdr sprintf(" rmse (%s table) |", m{1})];
  endfor
  L{end+1} = [hdr " fit time (s) |"];
  L{end+1} = ["|---|---|---|---|---|---|---|" repmat("---|", 1, numel (otables)) "---|"];
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    F = D.(fieldname (mat)).F;
    for mth = c.methods
      r = F.(mth{1});
      for k = c.lobes
        row = sprintf ("| %s | %s | %d | %.4g | %.4g | %.4g | %.4g |", mat, mth{1}, k,
                       mean (r.errors.inplane.rmse(k,:)), mean (r.errors.inplane.rel_rmse(k,:)),
                       mean (r.errors.inplane.log_rmse(k,:)), mean (r.errors.inplane.cos_rmse(k,:)));
        for m = otables
          row = [row sprintf(" %.4g |", mean (r.errors.(m{1}).rmse(k,:)))];
        endfor
        L{end+1} = [row sprintf(" %.2f |", max (r.lobe_time(k,:)))];
      endfor
    endfor
  endfor
  L{end+1} = "";
  for i = 1:numel (c.materials)
    L{end+1} = sprintf ("![in-plane data and fits, %s](figures/plane-%s.png)",
                        strrep (c.materials{i}, "-", " "), c.materials{i});
  endfor
  L{end+1} = "";
  L{end+1} = "Parameters of the in-plane fits (the paper's layout; JSON, text and BRDF Explorer files in `fit/`):";
  L{end+1} = "";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    for k = c.lobes
      L{end+1} = "```";
      L{end+1} = strtrim (fileread ([repro_files("model", c.results, mat, "inplane", k) ".txt"]));
      L{end+1} = "```";
    endfor
  endfor
  L{end+1} = "";
  ## --- error against run time
  L{end+1} = "## Error against run time";
  L{end+1} = "";
  L{end+1} = "### Fitting";
  L{end+1} = "";
  L{end+1} = "Time until the fit's error (rmse of the best parameters so far, growing from 1 to 3 lobes) came within 10% and within 1% of its final value, per channel.";
  L{end+1} = "";
  L{end+1} = "| material | channel | final rmse | time to +10% (s) | time to +1% (s) | total (s) |";
  L{end+1} = "|---|---|---|---|---|---|";
  chn = {"R", "G", "B"};
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    F = D.(fieldname (mat)).F;
    for ch = 1:3
      T = F.inplane.trace;                # K x 2 per channel, as jsondecode returns them
      if (iscell (T))
        T = T{ch};
      else
        T = reshape (T(ch,:,:), [], 2);
      endif
      fin = T(end,2);
      t10 = T(find (T(:,2) <= 1.1 * fin, 1), 1);
      t1 = T(find (T(:,2) <= 1.01 * fin, 1), 1);
      L{end+1} = sprintf ("| %s | %s | %.4g | %.3f | %.3f | %.3f |", mat, chn{ch}, fin, t10, t1, T(end,1));
    endfor
  endfor
  L{end+1} = "";
  L{end+1} = "![fit error against run time](figures/fit-trace.png)";
  L{end+1} = "";
  L{end+1} = "### Rendering";
  L{end+1} = "";
  L{end+1} = sprintf ("The measured data rendered by rt_render with fewer samples per pixel, against the %d-spp render.", c.spp);
  L{end+1} = "";
  L{end+1} = "| material | spp | render time (s) | PSNR (dB) |";
  L{end+1} = "|---|---|---|---|";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    P = D.(fieldname (mat)).P;
    for j = 1:numel (P.spp)
      L{end+1} = sprintf ("| %s | %d | %.2f | %.2f |", mat, P.spp(j), P.time(j), P.psnr(j));
    endfor
    L{end+1} = sprintf ("| %s | %d (reference) | %.2f | - |", mat, P.reference_spp, P.reference_time);
  endfor
  L{end+1} = "";
  L{end+1} = "![render PSNR against run time](figures/spp.png)";
  L{end+1} = "";
  E1 = D.(fieldname (c.materials{1})).P.env;
  L{end+1} = sprintf ("Under the environment light '%s' (one ray per pixel centre), with fewer light samples per pixel, against the %d-sample render (FLIP: 0 = the same, lower is better).",
                      E1.map, E1.reference);
  L{end+1} = "";
  L{end+1} = "| material | light samples | render time (s) | FLIP | PSNR (dB) |";
  L{end+1} = "|---|---|---|---|---|";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    E = D.(fieldname (mat)).P.env;
    for j = 1:numel (E.samples)
      L{end+1} = sprintf ("| %s | %d | %.2f | %.3f | %.2f |", mat, E.samples(j), E.time(j), E.flip(j), E.psnr(j));
    endfor
    L{end+1} = sprintf ("| %s | %d (reference) | %.2f | - | - |", mat, E.reference, E.reference_time);
  endfor
  L{end+1} = "";
  L{end+1} = "![render FLIP against run time, environment light](figures/env-samples.png)";
  L{end+1} = "";
  L{end+1} = "### Render times";
  L{end+1} = "";
  L{end+1} = sprintf ("The paper: about 345 s per 256 x 512 image at 128 rays per pixel (pbrt, 2.3 GHz dual-core laptop). Here (%d x %d):", scene.width, scene.height);
  L{end+1} = "";
  L{end+1} = "| material | measured, rt_render (s) | material memory (bytes) | 1/2/3-lobe fits, POV-Ray (s) | 1/2/3-lobe fits, rt_render (s) |";
  L{end+1} = "|---|---|---|---|---|";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    X = D.(fieldname (mat));
    L{end+1} = sprintf ("| %s | %.1f | %d | %s | %s |", mat, X.M.info.time_total, X.M.info.material_bytes,
                        strjoin (arrayfun (@(v) sprintf ("%.1f", v), [X.R.inplane.pov_time], "uniformoutput", false), " / "),
                        strjoin (arrayfun (@(v) sprintf ("%.1f", v), [X.R.inplane.rt_time], "uniformoutput", false), " / "));
  endfor
  L{end+1} = "";
  txt = strjoin (L, "\n");
  repro_save (repro_files ("report", c.results, ""), [txt "\n"]);
  sm.settings = struct ("scene", scene.name, "width", scene.width, "height", scene.height,
                        "spp", scene.spp, "pov_antialias", c.pov_aa, "max_angle", c.max_angle,
                        "quick", c.quick);
  repro_save (repro_files ("summary", c.results, ""), sm);
  printf ("reproduce: wrote %s and %s\n", repro_files ("report", c.results, ""),
          repro_files ("summary", c.results, ""));
endfunction

## the paper's method is the report's first column and its reference
function need_inplane (c)
  if (! any (strcmp (c.methods, "inplane")))
    error ("lafortune:badConfig",
           "repro_report: METHODS is '%s': make reproduce needs the paper's method, inplane",
           strjoin (c.methods, " "));
  endif
endfunction


## the best model of each material at each lobe count, by the FLIP of the
## POV-Ray renders, each model's best over the methods (repro_models)
function [L, S] = models_section (c, L, D)
  mats = c.materials;
  F = struct ();
  held = ! isempty (c.judge);
  for m = c.methods
    F.(m{1}) = nan (numel (mats), numel (c.lobes));
    for i = 1:numel (mats)
      X = D.(fieldname (mats{i}));
      if (held)
        F.(m{1})(i,:) = repro_row (X.J.(m{1}), "flip_mean", numel (c.lobes));
      else
        F.(m{1})(i,:) = [X.R.(m{1}).flip_pov];
      endif
    endfor
  endfor
  [M, B] = repro_models (c, F);
  L{end+1} = "## The best model";
  L{end+1} = "";
  L{end+1} = sprintf (["The models of MODELS (%s), each fitted by every method (`brdf_fit`), judged by %s: " ...
                       "per model the best fit over the methods (its FLIP and method), " ...
                       "and the model with the lowest FLIP (`make database MODELS=\"lafortune cooktorrance ggx\"` " ...
                       "compares them over a database)."], strjoin ({M.model}, ", "),
                      ifelse (held, "the mean FLIP under the held-out lights (JUDGE)",
                              "the in-sample FLIP of their POV-Ray renders (JUDGE is empty)"));
  L{end+1} = "";
  hdr = "| material | lobes |";
  for t = 1:numel (M)
    hdr = [hdr sprintf(" %s: FLIP (method) |", M(t).model)];
  endfor
  L{end+1} = [hdr " best model |"];
  L{end+1} = ["|---|---|" repmat("---|", 1, numel (M)) "---|"];
  S = struct ();
  for i = 1:numel (mats)
    for j = 1:numel (c.lobes)
      row = sprintf ("| %s | %d |", mats{i}, c.lobes(j));
      for t = 1:numel (M)
        row = [row sprintf(" %.4f (%s) |", M(t).flip(i,j), M(t).method{i,j})];
      endfor
      L{end+1} = [row sprintf(" **%s** |", B.model{i,j})];
    endfor
    S.(fieldname (mats{i})) = struct ("model", {B.model(i,:)}, "method", {B.method(i,:)}, "flip", B.flip(i,:));
  endfor
  L{end+1} = "";
endfunction

## the held-out verdicts: every fit under the lights of JUDGE (repro_judge),
## in-sample FLIP beside them, and per material and lobe count the method
## with the lowest held-out FLIP
function [L, S] = heldout_section (c, L, D)
  S = struct ("lights", {{c.judge.label}}, "best_method", struct ());
  L{end+1} = "## Held-out verdicts: every fit in light it was not made for";
  L{end+1} = "";
  if (isempty (c.judge))
    L{end+1} = ["JUDGE is empty: no held-out light. Every score in this report is in-sample for the scene fit " ...
                "(judged in the light it was made for), so no verdict is made."];
    L{end+1} = "";
    return;
  endif
  nl = numel (c.judge);
  L{end+1} = sprintf (["The pipeline's scene lit by each light of JUDGE (%s; environments with %d light samples per " ...
                       "pixel sample, %d sample%s per pixel), which no fit was made for: the measured data and every " ...
                       "fit rendered by rt_render with the same samples, compared by FLIP (lower is better). " ...
                       "In-sample: the FLIP of the POV-Ray render in the scene's own light, the light the scene fit was made for. " ...
                       "The held-out mean is the verdict."], strjoin ({c.judge.label}, ", "), c.judge_samples,
                      c.judge_spp, ifelse (c.judge_spp == 1, "", "s"));
  L{end+1} = "";
  hdr = "| material | method | lobes | in-sample FLIP |";
  for l = 1:nl
    hdr = [hdr sprintf(" %s |", c.judge(l).label)];
  endfor
  L{end+1} = [hdr " **held-out mean** | held-out ΔE |"];
  L{end+1} = ["|---|---|---|---|" repmat("---|", 1, nl) "---|---|"];
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    X = D.(fieldname (mat));
    best = repmat ({""}, 1, numel (c.lobes));
    bf = Inf (1, numel (c.lobes));
    for m = c.methods
      r = X.J.(m{1});
      for j = 1:numel (c.lobes)
        row = sprintf ("| %s | %s | %d | %.4f |", mat, repro_method (m{1}).label, c.lobes(j), X.R.(m{1})(j).flip_pov);
        f = r(j).flip(:)';
        for l = 1:nl
          row = [row sprintf(" %.4f |", f(l))];
        endfor
        L{end+1} = [row sprintf(" **%.4f** | %.2f |", r(j).flip_mean, r(j).deltae_mean)];
        if (r(j).flip_mean < bf(j))
          bf(j) = r(j).flip_mean;
          best{j} = m{1};
        endif
      endfor
    endfor
    S.best_method.(fieldname (mat)) = struct ("method", {best}, "flip", bf);
  endfor
  L{end+1} = "";
  L{end+1} = "The best method by held-out FLIP, per material and lobe count:";
  L{end+1} = "";
  for i = 1:numel (c.materials)
    b = S.best_method.(fieldname (c.materials{i}));
    L{end+1} = sprintf ("- %s: %s", c.materials{i},
                        strjoin (arrayfun (@(j) sprintf ("%d lobe%s: %s (%.4f)", c.lobes(j),
                                                         ifelse (c.lobes(j) > 1, "s", ""), b.method{j}, b.flip(j)),
                                           1:numel (c.lobes), "uniformoutput", false), "; "));
  endfor
  L{end+1} = "";
  for i = 1:numel (c.materials)
    L{end+1} = sprintf ("![the fits under %s (held out), %s](figures/heldout-%s.png)", c.judge(1).label,
                        strrep (c.materials{i}, "-", " "), c.materials{i});
  endfor
  L{end+1} = "";
endfunction

function f = fieldname (mat)
  f = strrep (mat, "-", "_");
endfunction

function s = ifelse (c, a, b)
  if (c) s = a; else s = b; endif
endfunction

function s = scene_desc (c)
  if (isempty (c.mesh))
    s = sprintf ("the built-in scene '%s'; give MESH=happy_vrip.ply for the paper's Happy Buddha", c.scene);
  else
    s = c.mesh;
  endif
endfunction

## the fits judged as a viewer sees them: FLIP, CIEDE2000 and the hue
## statistic of every render (img_compare, in the render step's records)
function L = perceptual_section (c, L, D)
  L{end+1} = "## The fits as a viewer sees them: FLIP and colour difference";
  L{end+1} = "";
  L{end+1} = ["PSNR is relative to the measured render's peak, the specular highlight, often a thousand times the rest of the picture, " ...
              "so it hardly sees the body colour: a grey sphere for a teal paint can score above the paper. " ...
              "Here every render is also compared as a viewer sees it (`img_compare`): **FLIP** (HDR-FLIP, Andersson et al. 2020/2021: " ...
              "the mean per-pixel perceived difference over the object, 0 = same, 1 = most different; exposures by the published rule " ...
              "on the measured render's object pixels), **ΔE** (the mean CIEDE2000 difference of the displayed images over the object; " ...
              "about 1 is just noticeable, above 10 a different colour) and **hue** (the chroma-weighted mean hue-angle difference in degrees: " ...
              "a body or highlight of the wrong colour). Lower is better for all three. POV-Ray / rt_render."];
  L{end+1} = "";
  L{end+1} = "| material | method | lobes | PSNR (dB) | FLIP | ΔE | hue (deg) |";
  L{end+1} = "|---|---|---|---|---|---|---|";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    R = D.(fieldname (mat)).R;
    for m = c.methods
      for j = 1:numel (c.lobes)
        r = R.(m{1})(j);
        L{end+1} = sprintf ("| %s | %s | %d | %.2f / %.2f | %.4f / %.4f | %.2f / %.2f | %.1f / %.1f |",
                            mat, repro_method (m{1}).label, c.lobes(j), r.psnr_pov, r.psnr_rt, r.flip_pov, r.flip_rt,
                            r.deltae_pov, r.deltae_rt, r.hue_pov, r.hue_rt);
      endfor
    endfor
  endfor
  L{end+1} = "";
endfunction

## the study of tables and weightings against the picture
function L = study_section (c, L)
  L{end+1} = "## Which fit looks right: tables and weightings against the picture";
  L{end+1} = "";
  L{end+1} = ["Each material fitted from each table (in-plane: the paper's; hemisphere: every valid bin, weighted by its solid angle; " ...
              "scene: the angle pairs the scene's pixels see, `merl_scene`) with each weighting of the residuals " ...
              "(plain, cosine: times cos theta_i as Ngan et al. 2005, relative, log; image: each pair's share of the image times its irradiance squared, " ...
              "the image's MSE). PSNR of each fit's POV-Ray render against the measured data's POV-Ray render, in the scene " ...
              "(A) and in a second scene lit from another direction (B), and the FLIP of A (lower is better); `pred.` is the PSNR the scene table predicts for A " ...
              "(`brdf_error (model, S, \"psnr\")`). The paper's method is the first row. A is in-sample for the scene " ...
              "table's fits (they were made for that light), B is held out for all of them."];
  L{end+1} = "";
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    R = jsondecode (fileread (repro_files ("study", c.results, mat)));
    nl = max (c.lobes);
    hdr = "| table | weighting |";
    for k = 1:nl
      hdr = [hdr sprintf(" A, %d | B, %d |", k, k)];
    endfor
    for k = 1:nl
      hdr = [hdr sprintf(" FLIP A, %d |", k)];
    endfor
    L{end+1} = sprintf ("**%s** (second scene lit from [%s]):", mat, num2str (R.light_b(:)', "%.2f "));
    L{end+1} = "";
    L{end+1} = [hdr " pred. A | fit (s) |"];
    L{end+1} = ["|---|---|" repmat("---|---|", 1, nl) repmat("---|", 1, nl) "---|---|"];
    for m = R.methods(:)'
      row = sprintf ("| %s | %s |", m.table, m.weight);
      for k = 1:nl
        row = [row sprintf(" %.2f | %.2f |", m.psnr_a(k), m.psnr_b(k))];
      endfor
      for k = 1:nl
        row = [row sprintf(" %.4f |", m.flip_a(k))];
      endfor
      pr = "-";
      if (all (isfinite (m.psnr_a_predicted)))
        pr = strjoin (arrayfun (@(v) sprintf ("%.1f", v), m.psnr_a_predicted(:)', "uniformoutput", false), " / ");
      endif
      L{end+1} = [row sprintf(" %s | %.1f |", pr, m.fit_time)];
    endfor
    L{end+1} = "";
    L{end+1} = sprintf ("![PSNR against lobes, %s](figures/study-%s.png)", mat, mat);
    L{end+1} = sprintf ("![FLIP against lobes, %s](figures/study-flip-%s.png)", mat, mat);
    L{end+1} = "";
  endfor
endfunction
