## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} db_report ()
## Merge step of `make database`: from the per-material records in
## RESULTS/materials/MATERIAL/ (fit/, render/, sheet/) of every material in
## MATERIALS, write into RESULTS:
##
## @table @file
## @item table.csv
## one row per material, fit method and lobe count (and its model type,
## @code{model}: METHODS crossed with MODELS, repro_method): PSNR, FLIP, ΔE
## (CIEDE2000) and the hue statistic of the fit's render with POV-Ray
## (@code{_pov}) and with rt_render (@code{_rt}) against the measured data
## rendered by the same renderer (img_compare) in the scene's own light
## (in-sample for the scene fits), the same four as means over the
## held-out lights of JUDGE (@code{_heldout}, repro_judge) and the FLIP
## under each of them (@code{flip_heldout_LIGHT}), errors (rmse, log rmse
## and cosine-weighted rmse as Ngan et al. 2005, means over R, G, B, on
## each method's table), fit time, render times, the model's size
## (@code{params}: the numbers it holds, @code{json_bytes}: its JSON
## file), its largest albedo (@code{albedo_max}, for the types brdf_fit
## reports it of) and its parameters (the columns of every type's fields); a
## material whose file could not be read or processed gets one row with
## status @code{error} and the message.
## @item report.md
## the summary across materials (in-sample median PSNR, FLIP, ΔE and hue,
## worst and best PSNR and worst FLIP, and the held-out median FLIP and
## ΔE, per method and lobe count), the published baseline, the pairs of
## fits that PSNR and FLIP rank differently, and the verdicts, all on the
## held-out mean FLIP (on the in-sample FLIP only with JUDGE empty, which
## the report then says): the materials where the recommended fit
## (general) renders worse with one more lobe (FAIL_FLIP_DROP), where the
## Lafortune model fails (FAIL_FLIP, FAIL_FLIP_GAIN; PSNR beside it), the
## models compared (MODELS: the best model per material and lobe count,
## medians per model for metals and non-metals, Lavoué's split, sizes,
## energy, where Lafortune loses; db_models); every material's numbers,
## times per stage, and the plots @file{figures/psnr-lobes.png} (in-sample
## PSNR) and @file{figures/flip-lobes.png} (the verdicts' FLIP) against the
## lobe count.
## @item gallery/index.html
## the contact sheets of all materials, in-sample and held out.
## @item summary.json
## the same numbers for machines.
## @end table
## @end deftypefn
function db_report ()
  c = repro_config ();
  mats = c.materials;
  S = repro_files ().steps;
  steps = {S([S.database]).name};
  D = struct ("material", mats, "ok", false, "error", "", "rec", [], "root", "");
  for i = 1:numel (mats)
    root = repro_files ("db_material", c.results, mats{i});
    D(i).root = root;
    rec = struct ();
    for s = steps
      f = repro_files (s{1}, root, mats{i});
      if (! exist (f, "file"))
        rec.(s{1}) = struct ("status", "error", "error", ["no record " f], "time", NaN);
      else
        rec.(s{1}) = jsondecode (fileread (f));
      endif
    endfor
    D(i).rec = rec;
    D(i).ok = all (cellfun (@(s) strcmp (rec.(s).status, "ok"), steps));
    for s = steps
      if (! strcmp (rec.(s{1}).status, "ok"))
        D(i).error = sprintf ("%s: %s", s{1}, rec.(s{1}).error);
        break;
      endif
    endfor
  endfor
  ok = find ([D.ok]);
  nm = numel (c.methods);
  nk = numel (c.lobes);
  ## every measure (materials x lobes) per method and renderer: X.flip.pov.scene,
  ## X.deltae.rt.inplane, ...; P and Q are PSNR with POV-Ray and rt_render
  X = struct ();
  for q = {"psnr", "flip", "deltae", "hue"}
    for r = {"pov", "rt"}
      for m = [c.methods, {"ngan2005"}]   # and the published fit, where there is one
        X.(q{1}).(r{1}).(m{1}) = nan (numel (mats), nk);
        for i = ok
          if (isfield (D(i).rec.render_fits, m{1}))
            X.(q{1}).(r{1}).(m{1})(i,:) = repro_row (D(i).rec.render_fits.(m{1}), [q{1} "_" r{1}], nk);
          endif
        endfor
      endfor
    endfor
  endfor
  ## held out: the means over JUDGE's lights (repro_judge, rt_render), which
  ## no fit was made for; every verdict is made on them ("verdict"), and on
  ## the in-sample POV-Ray renders only without held-out lights
  nj = numel (c.judge);
  for q = {"psnr", "flip", "deltae", "hue"}
    for m = [c.methods, {"ngan2005"}]
      X.(q{1}).heldout.(m{1}) = nan (numel (mats), nk);
      X.(q{1}).light.(m{1}) = nan (numel (mats), nk, nj);
      for i = ok
        if (isfield (D(i).rec.judge, m{1}))
          r = D(i).rec.judge.(m{1});
          n = min (numel (r), nk);
          X.(q{1}).heldout.(m{1})(i,1:n) = repro_row (r, [q{1} "_mean"], n);
          for l = 1:nj
            X.(q{1}).light.(m{1})(i,1:n,l) = arrayfun (@(x) x.(q{1})(l), r(1:n));
          endfor
        endif
      endfor
    endfor
    X.(q{1}).verdict = X.(q{1}).(ifelse (nj > 0, "heldout", "pov"));
  endfor
  if (nj > 0)
    X.verdict = sprintf ("held-out FLIP (the mean over %s, rt_render; no fit was made for these lights)",
                         strjoin ({c.judge.label}, ", "));
  else
    X.verdict = "in-sample FLIP (POV-Ray renders in the light the scene fits were made for: JUDGE is empty)";
  endif
  P = X.psnr.pov;
  Q = X.psnr.rt;
  F = X.flip.pov;
  Frt = X.flip.rt;
  V = X.flip.verdict;                    # the verdicts' measure
  Vp = X.psnr.verdict;

  ## --- table.csv
  ## the methods' models, the tables their errors are on (the methods
  ## without their models), the lobe fields of every model type fitted
  mp = cellfun (@repro_method, c.methods);
  err = unique ({mp.base}, "stable");
  pf = {};
  for t = unique ({mp.model}, "stable")
    pf = [pf, setdiff(brdf_model (t{1}).fields(2:end), pf, "stable")];
  endfor
  head = {"material", "method", "model", "lobes", "status", "error", "psnr_db", "psnr_rt_db", "flip_pov", ...
          "flip_rt", "deltae_pov", "deltae_rt", "hue_pov", "hue_rt"};
  for t = err
    head = [head, strcat({"rmse_", "log_rmse_", "cos_rmse_"}, t{1})];
  endfor
  head = [head, {"flip_heldout", "deltae_heldout", "psnr_heldout", "hue_heldout"}, ...
          strcat("flip_heldout_", regexprep ({c.judge.name}, "[^A-Za-z0-9]+", "_"))];
  head = [head, {"fit_time_s", "render_time_s", "measured_render_time_s", "params", "json_bytes", ...
                 "albedo_max", "rho_d_r", "rho_d_g", "rho_d_b"}];
  chn = "rgb";
  for j = 1:max (c.lobes)
    for p = pf
      for ch = 1:3
        head{end+1} = sprintf ("%s%d_%s", lower (p{1}), j, chn(ch));
      endfor
    endfor
  endfor
  rows = {strjoin(head, ",")};
  for i = 1:numel (mats)
    if (! D(i).ok)
      rows{end+1} = csv_row ([{mats{i}, "", "", "", "error", D(i).error}, repmat({""}, 1, numel (head) - 6)]);
      continue;
    endif
    Fi = D(i).rec.fit;
    R = D(i).rec.render_fits;
    for q = 1:numel (c.methods)
      m = c.methods(q);
      r = Fi.(m{1});
      for j = 1:nk
        k = c.lobes(j);
        v = {mats{i}, m{1}, mp(q).model, k, "ok", ""};
        for q2 = {"psnr", "flip", "deltae", "hue"}
          v = [v, {X.(q2{1}).pov.(m{1})(i,j), X.(q2{1}).rt.(m{1})(i,j)}];
        endfor
        for t = err
          e = r.errors.(t{1});
          v = [v, {mean(e.rmse(k,:)), mean(e.log_rmse(k,:)), mean(e.cos_rmse(k,:))}];
        endfor
        v = [v, heldout_cells(X, m{1}, i, j, nj)];
        md = r.parameters(k);             # the fit record's parameters
        alb = "";
        if (isfield (r, "albedo"))
          alb = max (r.albedo(k,:));
        endif
        v = [v, {max(r.lobe_time(k,:)), R.(m{1})(j).pov_time, D(i).rec.render_measured.info.time_total, ...
                 at(r, "params", k), at(r, "json_bytes", k), alb}, param_cells(md, k, pf, max (c.lobes))];
        rows{end+1} = csv_row (v);
      endfor
    endfor
    if (isfield (R, "ngan2005"))
      ## the published fit (PUBLISHED): its measures, render time, parameters
      r = R.ngan2005(1);
      md = lafortune_ngan (c.published, mats{i});
      v = {mats{i}, "ngan2005", "lafortune", 1, "ok", ""};
      for q = {"psnr", "flip", "deltae", "hue"}
        v = [v, {r.([q{1} "_pov"]), r.([q{1} "_rt"])}];
      endfor
      v = [v, repmat({""}, 1, 3 * numel (err)), heldout_cells(X, "ngan2005", i, 1, nj), {"", r.pov_time, D(i).rec.render_measured.info.time_total, ...
                                                  "", "", ""}, param_cells(md, 1, pf, max (c.lobes))];
      rows{end+1} = csv_row (v);
    endif
  endfor
  repro_save (repro_files ("table", c.results, ""), [strjoin(rows, "\n") "\n"]);

  ## --- the plots: PSNR (in-sample) and FLIP (the verdicts') against lobe
  ## count, every material
  plot_lobes_db (P, c, mats, "in-sample PSNR against the measured render (dB), POV-Ray", [],
                 [], repro_files ("fig_psnr_lobes", c.results, ""));
  plot_lobes_db (V, c, mats, ifelse (nj > 0, "held-out FLIP, mean over JUDGE's lights (lower is better)",
                                     "in-sample FLIP, POV-Ray (lower is better)"), [0 1],
                 c.fail_flip, repro_files ("fig_flip_lobes", c.results, ""));

  ## --- report.md
  L = {"# lafortune: the Lafortune model over a database of measured BRDFs", ""};
  scene = repro_scene (c);
  L{end+1} = sprintf (["%d materials from `%s` (%d processed, %d failed). Scene `%s`, %d x %d pixels " ...
                       "(W x H), %d samples per pixel for the measured data (rt_render); fits rendered with " ...
                       "POV-Ray (anti-aliasing %d); fits of %s lobes, grazing angles beyond %d degrees left " ...
                       "out; %s, Octave %s."], numel (mats), c.merl_dir, numel (ok), numel (mats) - numel (ok),
                      scene.name, scene.width, scene.height, scene.spp, c.pov_aa, mat2str (c.lobes),
                      c.max_angle, datestr (now (), "yyyy-mm-dd HH:MM"), OCTAVE_VERSION);
  L{end+1} = "";
  L{end+1} = ["Each fit's render is compared with the measured-data render (`img_compare`): " ...
              "PSNR, 10 log10 (peak^2 / MSE), peak = the measured render's maximum (dominated by the " ...
              "specular highlight; higher is better); FLIP, HDR-FLIP (Andersson et al. 2021), the mean " ...
              "per-pixel error over the object's pixels, 0 (same) to 1, as a viewer flipping between the " ...
              "two pictures sees them (lower is better); ΔE, the mean CIEDE2000 difference of the " ...
              "displayed pictures over the object's pixels (about 1: just noticeable; lower is better); " ...
              "hue, the chroma-weighted mean hue-angle difference in degrees (a body or highlight of the " ...
              "wrong colour; lower is better). Everything per row is in `table.csv`; the contact sheets " ...
              "are in `gallery/index.html`."];
  L{end+1} = "";
  L{end+1} = "## Summary across materials";
  L{end+1} = "";
  ag = [];
  for i = ok
    for m = c.methods
      ag = [ag, [D(i).rec.render_fits.(m{1}).renderers_psnr]];
    endfor
  endfor
  if (isempty (ag))
    ag = NaN;
  endif
  L{end+1} = sprintf (["Measures of the POV-Ray renders (the fits' renderer, as the paper used one) and, in the " ...
                       "column rt_render, of the Octave raytracer's, which evaluates each model per sample (each " ...
                       "against the measured data rendered by the same renderer). The two renderers agree on the " ...
                       "same model to %.1f dB at worst, %.1f dB in the median over the %d fits."],
                      min (ag), median (ag), numel (ag));
  L{end+1} = "";
  L{end+1} = ["| method | lobes | in-sample: median PSNR (dB) | median FLIP | median ΔE | median hue (°) | " ...
              "worst PSNR (dB) | worst material | best PSNR (dB) | worst FLIP | worst material (FLIP) | " ...
              "rt_render: median PSNR (dB), FLIP, ΔE, hue (°) | median cosine-weighted rmse | " ...
              "**held out**: median FLIP, ΔE |"];
  L{end+1} = "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|";
  sm = struct ("materials", {mats}, "processed", numel (ok), "failed", {{}}, "methods", struct ());
  for m = c.methods
    for j = 1:nk
      x = P.(m{1})(ok,j);
      med = @(q, r) median (X.(q).(r).(m{1})(ok,j));
      cr = arrayfun (@(i) mean (D(i).rec.fit.(m{1}).errors.(repro_method (m{1}).base).cos_rmse(c.lobes(j),:)), ok);
      if (isempty (x))
        L{end+1} = sprintf ("| %s | %d |%s", repro_method (m{1}).label, c.lobes(j), repmat (" - |", 1, 12));
        continue;
      endif
      [w, iw] = min (x);
      [wf, iwf] = max (F.(m{1})(ok,j));
      L{end+1} = sprintf (["| %s | %d | %.2f | %.3f | %.2f | %.1f | %.2f | %s | %.2f | %.3f | %s | " ...
                           "%.2f, %.3f, %.2f, %.1f | %.4g | %.3f, %.2f |"], repro_method (m{1}).label, c.lobes(j),
                          median (x), med ("flip", "pov"), med ("deltae", "pov"), med ("hue", "pov"),
                          w, mats{ok(iw)}, max (x), wf, mats{ok(iwf)},
                          med ("psnr", "rt"), med ("flip", "rt"), med ("deltae", "rt"), med ("hue", "rt"),
                          median (cr), med ("flip", "heldout"), med ("deltae", "heldout"));
      for q = {"psnr", "flip", "deltae", "hue"}
        sm.methods.(m{1}).(["median_" q{1}])(j) = med (q{1}, "pov");
        sm.methods.(m{1}).(["median_" q{1} "_rt"])(j) = med (q{1}, "rt");
        sm.methods.(m{1}).(["median_" q{1} "_heldout"])(j) = med (q{1}, "heldout");
      endfor
      sm.methods.(m{1}).worst_psnr(j) = w;
      sm.methods.(m{1}).worst_material{j} = mats{ok(iw)};
      sm.methods.(m{1}).worst_flip(j) = wf;
      sm.methods.(m{1}).worst_flip_material{j} = mats{ok(iwf)};
    endfor
  endfor
  L{end+1} = "";
  L{end+1} = sprintf ("![PSNR against lobe count, every material](%s)", repro_files ("fig_psnr_lobes", "", ""));
  L{end+1} = "";
  L{end+1} = sprintf ("![%s against lobe count, every material (dashed: FAIL_FLIP = %g)](%s)",
                      ifelse (nj > 0, "held-out FLIP", "in-sample FLIP"), c.fail_flip,
                      repro_files ("fig_flip_lobes", "", ""));
  L{end+1} = "";

  ## --- the published fit: Ngan et al.'s 1-lobe fits against the toolbox's
  [L, sm.published] = published_section (L, D, ok, mats, X, c);

  ## --- where PSNR and FLIP disagree
  L{end+1} = "## PSNR and FLIP";
  L{end+1} = "";
  [L, sm.rank_disagreement] = disagreement (L, P, F, Q, Frt, ok, mats, c, c.fail_flip_drop);
  rec = "general";                    # the recommended method
  if (any (strcmp (c.methods, rec)))
    [up, rise] = falls_of (V.(rec), ok, c.fail_flip_drop);
    [up_p, rise_p] = falls_of (F.(rec), ok, c.fail_flip_drop);
    L{end+1} = sprintf (["The recommended fit (%s) renders worse with one more lobe (up by more than %g, " ...
                         "FAIL_FLIP_DROP) by %s on: %s. By in-sample FLIP (POV-Ray, the scene's own light): %s."],
                        rec, c.fail_flip_drop, X.verdict, names_rise (mats, up, V.(rec), Vp.(rec), c.lobes, c.fail_flip_drop),
                        names_rise (mats, up_p, F.(rec), P.(rec), c.lobes, c.fail_flip_drop));
    sm.flip_rises = struct ("method", rec, "verdict", {mats(up)}, "largest_rise", max ([rise; 0]),
                            "in_sample", {mats(up_p)});
  else
    L{end+1} = sprintf ("The recommended fit (%s) is not among METHODS (%s).", rec, strjoin (c.methods, " "));
    sm.flip_rises = struct ("method", rec, "verdict", {{}}, "largest_rise", NaN, "in_sample", {{}});
  endif
  L{end+1} = "";

  ## --- where the Lafortune model fails: by FLIP, PSNR beside it
  L{end+1} = "## Where the Lafortune model fails";
  L{end+1} = "";
  L{end+1} = sprintf (["Judged by %s. A material fails when its best fit (the lowest FLIP, over the " ...
                       "Lafortune model's methods and lobe counts) has FLIP above %g (FAIL_FLIP: the picture looks wrong), or when " ...
                       "the method of that best fit looks wrong with %d lobe%s (FLIP above %g) and going to %d " ...
                       "lobes lowers its FLIP by less than %g (FAIL_FLIP_GAIN: more lobes do not help, as the " ...
                       "paper found by PSNR for red plastic; a material that %d lobe%s already render%s right " ...
                       "does not fail for that). A method falls on a material when one more lobe raises FLIP by " ...
                       "more than %g (FAIL_FLIP_DROP; as the paper's 3-lobe fits did by PSNR)."],
                      X.verdict, c.fail_flip, min (c.lobes), plural (min (c.lobes)), c.fail_flip, max (c.lobes),
                      c.fail_flip_gain, min (c.lobes), plural (min (c.lobes)),
                      ifelse (min (c.lobes) == 1, "s", ""), c.fail_flip_drop);
  L{end+1} = "";
  fails = {};
  lm = c.methods(strcmp ({mp.model}, "lafortune"));      # the Lafortune model's methods
  for i = ifelse (isempty (lm), [], ok)
    fb = cellfun (@(m) min (V.(m)(i,:)), lm);
    [best, b] = min (fb);
    if (! isfinite (best))
      continue;
    endif
    mb = lm{b};
    [~, jb] = min (V.(mb)(i,:));
    gain = V.(mb)(i,1) - V.(mb)(i,end);
    why = {};
    if (best > c.fail_flip)
      why{end+1} = sprintf ("FLIP above %g", c.fail_flip);
    endif
    if (nk > 1 && V.(mb)(i,1) > c.fail_flip && ! (gain >= c.fail_flip_gain))
      why{end+1} = sprintf ("more lobes do not help (FLIP down by less than %g)", c.fail_flip_gain);
    endif
    if (isempty (why))
      continue;
    endif
    fails{end+1} = struct ("material", mats{i}, "reason", strjoin (why, "; "), "method", mb,
                           "lobes", c.lobes(jb), "flip", best, "flip_in_sample", F.(mb)(i,jb),
                           "psnr", Vp.(mb)(i,jb), "best_psnr", max (cellfun (@(m) max (Vp.(m)(i,:)), lm)),
                           "flip_first", V.(mb)(i,1), "flip_last", V.(mb)(i,end),
                           "psnr_first", Vp.(mb)(i,1), "psnr_last", Vp.(mb)(i,end));
  endfor
  if (isempty (lm))
    L{end+1} = sprintf ("The Lafortune model is not among MODELS (%s).", strjoin (c.models, " "));
  elseif (isempty (fails))
    L{end+1} = sprintf ("No material fails (%d processed).", numel (ok));
  else
    L{end+1} = sprintf ("%d of the %d processed materials fail:", numel (fails), numel (ok));
    L{end+1} = "";
    L{end+1} = sprintf (["| material | why | best fit | its FLIP (in-sample, POV-Ray) | its PSNR (dB) | " ...
                         "FLIP, %d to %d lobes | PSNR, %d to %d lobes (dB) | best PSNR, any fit (dB) |"],
                        min (c.lobes), max (c.lobes), min (c.lobes), max (c.lobes));
    L{end+1} = "|---|---|---|---|---|---|---|---|";
    for f = fails
      x = f{1};
      L{end+1} = sprintf ("| %s | %s | %s, %d lobe%s | %.3f (%.3f) | %.2f | %.3f → %.3f | %.2f → %.2f | %.2f |",
                          x.material, x.reason, x.method, x.lobes, plural (x.lobes), x.flip, x.flip_in_sample,
                          x.psnr, x.flip_first, x.flip_last, x.psnr_first, x.psnr_last, x.best_psnr);
    endfor
  endif
  sm.fails = fails;
  L{end+1} = "";
  L{end+1} = "Per method:";
  L{end+1} = "";
  for m = c.methods
    best = min (V.(m{1})(ok,:), [], 2);
    gain = V.(m{1})(ok,1) - V.(m{1})(ok,end);
    high = ok(best > c.fail_flip);
    flat = ok(! (gain >= c.fail_flip_gain) & nk > 1);
    [falls, rise] = falls_of (V.(m{1}), ok, c.fail_flip_drop);
    [falls_rt, rise_rt] = falls_of (F.(m{1}), ok, c.fail_flip_drop);
    L{end+1} = sprintf (["- %s: best FLIP above %g: %s; more lobes do not help (FLIP down by less than %g): " ...
                         "%s; more lobes render worse: %s (in-sample, POV-Ray: %s)."],
                        repro_method (m{1}).label, c.fail_flip,
                        names_val (mats, high, min (V.(m{1})(high,:), [], 2), "FLIP %.3f"), c.fail_flip_gain,
                        names_val (mats, flat, V.(m{1})(flat,end) - V.(m{1})(flat,1),
                                   sprintf ("FLIP %%+.3f from %d to %d lobes", min (c.lobes), max (c.lobes))),
                        names_rise (mats, falls, V.(m{1}), Vp.(m{1}), c.lobes, c.fail_flip_drop),
                        names_rise (mats, falls_rt, F.(m{1}), P.(m{1}), c.lobes, c.fail_flip_drop));
    sm.methods.(m{1}).fails_high = mats(high);
    sm.methods.(m{1}).fails_flat = mats(flat);
    sm.methods.(m{1}).falls = mats(falls);
    sm.methods.(m{1}).largest_flip_rise = max ([rise; 0]);
    sm.methods.(m{1}).falls_in_sample = mats(falls_rt);
    sm.methods.(m{1}).largest_flip_rise_in_sample = max ([rise_rt; 0]);
  endfor
  bad = find (! [D.ok]);
  L{end+1} = "";
  if (isempty (bad))
    L{end+1} = "Every file was read and processed.";
  else
    L{end+1} = "Files that could not be processed (one row each in `table.csv`):";
    L{end+1} = "";
    for i = bad
      L{end+1} = sprintf ("- **%s**: %s", mats{i}, D(i).error);
      sm.failed{end+1} = struct ("material", mats{i}, "error", D(i).error);
    endfor
  endif
  L{end+1} = "";

  ## --- the models compared (MODELS)
  [L, sm.models] = db_models (L, c, D, ok, mats, X);      # on X.*.verdict

  L{end+1} = "## Every material";
  L{end+1} = "";
  L{end+1} = sprintf (["One row per material and method; each cell gives the %s-lobe fits in turn, " ...
                       "POV-Ray renders, then rt_render's."],
                      strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), ", "));
  L{end+1} = "";
  L{end+1} = ["| material | method | PSNR (dB) | FLIP | ΔE | hue (°) | rt_render PSNR (dB) | rt_render FLIP | " ...
              "rt_render ΔE | rt_render hue (°) | contact sheet |"];
  L{end+1} = "|---|---|---|---|---|---|---|---|---|---|---|";
  fmt = struct ("psnr", "%.2f", "flip", "%.3f", "deltae", "%.2f", "hue", "%.1f");
  for i = 1:numel (mats)
    if (! D(i).ok)
      L{end+1} = sprintf ("| %s | %s |", mats{i}, strjoin (repmat ({"failed"}, 1, 10), " | "));
      continue;
    endif
    for m = c.methods
      s = sprintf ("| %s | %s |", mats{i}, m{1});
      for r = {"pov", "rt"}
        for q = {"psnr", "flip", "deltae", "hue"}
          s = [s " " lobes_txt(X.(q{1}).(r{1}).(m{1})(i,:), fmt.(q{1})) " |"];
        endfor
      endfor
      L{end+1} = [s sprintf(" [sheet](%s/%s) |", repro_files ("db_material", "", mats{i}), D(i).rec.sheet.file)];
    endfor
  endfor
  L{end+1} = "";
  L{end+1} = "## Time per material by stage";
  L{end+1} = "";
  L{end+1} = "Seconds of each step (Octave start-up not included), over the processed materials.";
  L{end+1} = "";
  L{end+1} = "| stage | median (s) | max (s) | total (s) |";
  L{end+1} = "|---|---|---|---|";
  for s = steps
    t = arrayfun (@(i) D(i).rec.(s{1}).time, ok);
    if (isempty (t))
      t = NaN;
    endif
    L{end+1} = sprintf ("| %s | %.1f | %.1f | %.1f |", s{1}, median (t), max (t), sum (t));
    sm.stage_time.(s{1}) = t(:)';
  endfor
  L{end+1} = "";
  repro_save (repro_files ("report", c.results, ""), strjoin (L, "\n"));
  sm.psnr = P;
  sm.psnr_rt = Q;
  sm.flip = F;
  sm.flip_rt = Frt;
  sm.deltae = X.deltae.pov;
  sm.deltae_rt = X.deltae.rt;
  sm.hue = X.hue.pov;
  sm.hue_rt = X.hue.rt;
  sm.verdict = X.verdict;
  sm.heldout = struct ("lights", {{c.judge.label}}, "flip", X.flip.heldout, "deltae", X.deltae.heldout,
                       "psnr", X.psnr.heldout, "hue", X.hue.heldout);
  sm.settings = struct ("scene", scene.name, "width", scene.width, "height", scene.height,
                        "spp", scene.spp, "pov_antialias", c.pov_aa, "max_angle", c.max_angle,
                        "lobes", c.lobes, "methods", {c.methods}, "models", {c.models},
                        "metals", {c.metals}, "quick", c.quick,
                        "fail_flip", c.fail_flip, "fail_flip_gain", c.fail_flip_gain,
                        "fail_flip_drop", c.fail_flip_drop, "judge", {{c.judge.name}},
                        "judge_samples", c.judge_samples, "judge_spp", c.judge_spp);
  repro_save (repro_files ("summary", c.results, ""), sm);
  write_gallery (c, D, P, F, X.deltae.pov, X.flip.heldout);
  printf ("database: %d materials (%d failed): %s\n", numel (mats), numel (bad),
          repro_files ("report", c.results, ""));
endfunction

## The baseline: the published 1-lobe fits (PUBLISHED, rendered by
## repro_render_fits and judged by repro_judge as the method ngan2005)
## against the recommended method's 1-lobe fit, on the verdicts' measure
function [L, S] = published_section (L, D, ok, mats, X, c)
  S = struct ("materials", {{}}, "flip", [], "psnr", [], "deltae", [], "hue", [], "flip_in_sample", [],
              "recommended_flip", []);
  has = ok(arrayfun (@(i) isfield (D(i).rec.render_fits, "ngan2005"), ok));
  L{end+1} = "## The published fit";
  L{end+1} = "";
  if (isempty (has))
    L{end+1} = sprintf (["No published fit was rendered (PUBLISHED = `%s`: the table is absent, or has none " ...
                         "of these materials)."], c.published);
    L{end+1} = "";
    return;
  endif
  S.materials = mats(has);
  for q = {"flip", "psnr", "deltae", "hue"}
    S.(q{1}) = X.(q{1}).verdict.ngan2005(has,1)';
  endfor
  S.flip_in_sample = X.flip.pov.ngan2005(has,1)';
  L{end+1} = sprintf (["Ngan, Durand and Matusik (2005) published 1-lobe Lafortune fits (direction and exponent " ...
                       "shared by R, G, B) of %d of these materials (`%s`); each is rendered like the toolbox's " ...
                       "fits (row `ngan2005` of `table.csv`). Theirs were fitted to the real measurements, the " ...
                       "toolbox's to the very data they are compared with here. Judged by %s."], numel (has),
                      c.published, X.verdict);
  rec = "general";
  j1 = find (c.lobes == 1, 1);
  if (any (strcmp (c.methods, rec)) && ! isempty (j1))
    S.recommended_flip = X.flip.verdict.(rec)(has,j1)';
    win = S.recommended_flip < S.flip;
    L{end+1} = "";
    L{end+1} = sprintf (["The recommended 1-lobe fit (%s) is better than the published one on %d of %d " ...
                         "materials%s. Medians: FLIP %.3f (published) against %.3f; PSNR %.2f dB against %.2f dB."],
                        rec, sum (win), numel (has),
                        ifelse (all (win), "", sprintf (" (not on: %s)", strjoin (mats(has(! win)), ", "))),
                        median (S.flip), median (S.recommended_flip), median (S.psnr),
                        median (X.psnr.verdict.(rec)(has,j1)));
  endif
  L{end+1} = "";
  L{end+1} = "| material | published: PSNR (dB) | FLIP | ΔE | hue (°) | in-sample FLIP | recommended 1 lobe: PSNR (dB) | FLIP |";
  L{end+1} = "|---|---|---|---|---|---|---|---|";
  for n = 1:numel (has)
    i = has(n);
    sp = NaN; sf = NaN;
    if (! isempty (S.recommended_flip))
      sp = X.psnr.verdict.(rec)(i,j1); sf = S.recommended_flip(n);
    endif
    L{end+1} = sprintf ("| %s | %.2f | %.3f | %.2f | %.1f | %.3f | %.2f | %.3f |", mats{i}, S.psnr(n), S.flip(n),
                        S.deltae(n), S.hue(n), S.flip_in_sample(n), sp, sf);
  endfor
  L{end+1} = "";
endfunction

## the held-out cells of table.csv of method M's fit at lobe slot J of
## material I: mean FLIP, dE, PSNR, hue over the NJ lights, then each
## light's FLIP ("" without held-out lights or record)
function v = heldout_cells (X, m, i, j, nj)
  v = {X.flip.heldout.(m)(i,j), X.deltae.heldout.(m)(i,j), X.psnr.heldout.(m)(i,j), X.hue.heldout.(m)(i,j)};
  v = [v, num2cell(reshape (X.flip.light.(m)(i,j,:), 1, nj))];
  v(cellfun (@(x) isnan (x), v)) = {""};
endfunction

## R.(F)(K), "" when the record lacks it
function x = at (r, f, k)
  x = "";
  if (isfield (r, f) && numel (r.(f)) >= k)
    x = r.(f)(k);
  endif
endfunction

## the parameter cells of table.csv of the model MD with K lobes: rho_d,
## then per lobe 1 .. NL the lobe fields PF (of every model type fitted),
## empty for the fields its type has not and the lobes it has not
function v = param_cells (md, k, pf, nl)
  v = num2cell (md.rho_d(:)');
  for l = 1:nl
    for p = pf
      if (l <= k && isfield (md, p{1}))
        x = reshape (md.(p{1}), [], 3);
        v = [v, num2cell(x(l,:))];
      else
        v = [v, {"", "", ""}];
      endif
    endfor
  endfor
endfunction

## How many pairs of fits PSNR and FLIP rank differently (one says the first
## is better, the other the second), within each material (all its fits) and
## across materials (the same method and lobe count), and how many of them
## by more than GAP of FLIP; appends the sentence to L
function [L, S] = disagreement (L, P, F, Q, Frt, ok, mats, c, gap)
  S = struct ();
  ex = "";
  nk = numel (c.lobes);
  for r = {"pov", "rt"}
    if (strcmp (r{1}, "pov"))
      A = P;  B = F;
    else
      A = Q;  B = Frt;
    endif
    w = a = zeros (1, 3);          # pairs, ranked differently, ... by more than GAP of FLIP
    best = [];
    for i = ok
      pa = cellfun (@(m) A.(m)(i,:), c.methods, "uniformoutput", false);
      pb = cellfun (@(m) B.(m)(i,:), c.methods, "uniformoutput", false);
      [n, e] = discordant ([pa{:}], [pb{:}], gap);
      w += n;
      ## the pair ranked differently with the largest FLIP difference (an example)
      if (strcmp (r{1}, "pov") && ! isempty (e) && (isempty (best) || e(1) > best(1)))
        best = [e i];
      endif
    endfor
    for m = c.methods
      for j = 1:nk
        a += discordant (A.(m{1})(ok,j), B.(m{1})(ok,j), gap);
      endfor
    endfor
    S.(r{1}) = struct ("within_pairs", w(1), "within_differ", w(2), "within_differ_gap", w(3),
                       "across_pairs", a(1), "across_differ", a(2), "across_differ_gap", a(3));
    if (! isempty (best))
      i = best(4);
      fit = @(q) sprintf ("%s %d", c.methods{ceil (q / nk)}, c.lobes(mod (q - 1, nk) + 1));
      pv = @(X, q) X.(c.methods{ceil (q / nk)})(i, mod (q - 1, nk) + 1);
      ex = sprintf ([" The widest such pair: on %s, PSNR prefers %s (%.2f dB, FLIP %.3f) to %s (%.2f dB, " ...
                     "FLIP %.3f)."], mats{i}, fit (best(2)), pv (P, best(2)), pv (F, best(2)), fit (best(3)),
                    pv (P, best(3)), pv (F, best(3)));
    endif
  endfor
  pct = @(d, n) 100 * d / max (n, 1);
  L{end+1} = sprintf (["PSNR and FLIP rank %d of %d pairs of fits of the same material differently (%.0f %%; " ...
                       "%d with FLIP apart by more than %g), and %d of %d pairs of materials fitted by the same " ...
                       "method with the same lobe count (%.0f %%; %d by more than %g): POV-Ray renders; with " ...
                       "rt_render's, %d of %d and %d of %d. A pair is ranked differently when one measure " ...
                       "finds the first fit better and the other the second (pairs that either finds equal " ...
                       "agree).%s"],
                      S.pov.within_differ, S.pov.within_pairs, pct (S.pov.within_differ, S.pov.within_pairs),
                      S.pov.within_differ_gap, gap, S.pov.across_differ, S.pov.across_pairs,
                      pct (S.pov.across_differ, S.pov.across_pairs), S.pov.across_differ_gap, gap,
                      S.rt.within_differ, S.rt.within_pairs, S.rt.across_differ, S.rt.across_pairs, ex);
  L{end+1} = "";
endfunction

## N = [pairs, ranked differently, ... with B apart by more than GAP]: pairs
## of entries where both A (PSNR: higher is better) and B (FLIP: lower is
## better) are finite, and those where A and B disagree; E = [FLIP gap,
## first, second] of the pair ranked differently with the largest FLIP gap
## (the first preferred by PSNR), empty when none
function [N, e] = discordant (a, b, gap)
  a = a(:);
  b = b(:);
  q = find (isfinite (a) & isfinite (b));
  [i, j] = find (triu (true (numel (q)), 1));
  i = q(i);
  j = q(j);
  da = a(i) - a(j);
  db = b(i) - b(j);
  bad = da .* db > 0;               # higher PSNR and higher FLIP
  N = [numel(i), nnz(bad), nnz(bad & abs (db) > gap)];
  e = [];
  if (N(2) > 0)
    [g, k] = max (abs (db) .* bad);
    if (da(k) > 0)
      e = [g, i(k), j(k)];
    else
      e = [g, j(k), i(k)];
    endif
  endif
endfunction

## The materials (indices into OK) whose FLIP X (materials x lobes) rises
## by more than LIMIT with one more lobe, and every material's largest rise
function [falls, rise] = falls_of (X, ok, limit)
  rise = zeros (numel (ok), 1);
  if (columns (X) > 1)
    rise = max (diff (X(ok,:), 1, 2), [], 2);
  endif
  falls = ok(rise > limit);
endfunction

## the materials IDX with their FLIP rises by more than LIMIT, each step
## "K1 → K2 lobes: FLIP +x (PSNR +y dB)"; FLIP F, PSNR P: materials x lobes
function s = names_rise (mats, idx, F, P, lobes, limit)
  if (isempty (idx))
    s = "none";
    return;
  endif
  t = {};
  for i = idx(:)'
    d = diff (F(i,:));
    st = {};
    for j = find (d > limit)
      st{end+1} = sprintf ("%d → %d lobes: FLIP %+.3f, PSNR %+.2f dB", lobes(j), lobes(j+1), d(j),
                           P(i,j+1) - P(i,j));
    endfor
    t{end+1} = sprintf ("%s (%s)", mats{i}, strjoin (st, "; "));
  endfor
  s = strjoin (t, ", ");
endfunction

function s = lobes_txt (v, fmt = "%.2f")
  s = strjoin (arrayfun (@(x) sprintf (fmt, x), v, "uniformoutput", false), " / ");
endfunction

function s = plural (k)
  s = ifelse (k == 1, "", "s");
endfunction

## the materials IDX with their values V, e.g. "gold (FLIP 0.612)"
function s = names_val (mats, idx, v, fmt)
  if (isempty (idx))
    s = "none";
  else
    s = strjoin (arrayfun (@(j) sprintf (["%s (" fmt ")"], mats{idx(j)}, v(j)), 1:numel (idx),
                           "uniformoutput", false), ", ");
  endif
endfunction

function s = csv_row (v)
  for j = 1:numel (v)
    x = v{j};
    if (isnumeric (x))
      if (isempty (x) || isnan (x))
        v{j} = "";
      else
        v{j} = sprintf ("%.6g", x);
      endif
    elseif (any (x == ',') || any (x == '"') || any (x == "\n"))
      v{j} = ['"' strrep(strrep (x, "\n", " "), '"', '""') '"'];
    endif
  endfor
  s = strjoin (v, ",");
endfunction

## one panel per method: the measure X.(method) (materials x lobes) against
## the lobe count, one line per material named at its end; YLAB the axis
## label, YL its limits ([]: from the values), LIMIT a threshold drawn dashed
## ([]: none); written to FILE
function plot_lobes_db (X, c, mats, ylab, yl, limit, file)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  nm = numel (c.methods);
  h = figure ("visible", "off", "position", [0 0 520 * nm 560]);
  ## the same axis for every method
  if (isempty (yl))
    v = cell2mat (cellfun (@(m) X.(m)(:), c.methods(:), "uniformoutput", false));
    v = v(isfinite (v));
    yl = [0 50];
    if (! isempty (v))
      yl = [floor(min (v)) - 1, ceil(max (v)) + 1];
    endif
  endif
  for i = 1:nm
    m = c.methods{i};
    subplot (1, nm, i);
    Y = X.(m);
    col = lines (rows (Y));
    ## the names at the line ends, spread apart so that none overlaps
    ok = find (isfinite (Y(:,end)))';
    ly = spread (Y(ok,end), (yl(2) - yl(1)) * 11 / 460, yl);
    for q = 1:numel (ok)
      r = ok(q);
      plot (c.lobes, Y(r,:), "-o", "linewidth", 1, "color", col(r,:));
      hold on;
      plot ([c.lobes(end), c.lobes(end) + 0.25], [Y(r,end), ly(q)], "-", "color", col(r,:));
      text (c.lobes(end) + 0.3, ly(q), mats{r}, "fontsize", 7, "interpreter", "none",
            "color", col(r,:) * 0.8);
    endfor
    if (! isempty (limit))
      plot ([min(c.lobes) - 0.2, max(c.lobes) + 1.2], [limit limit], "--k", "linewidth", 1);
      hold on;
      text (min (c.lobes) - 0.15, limit, sprintf ("FAIL_FLIP %g", limit), "fontsize", 7,
            "interpreter", "none", "verticalalignment", "bottom");
    endif
    hold off;
    xlim ([min(c.lobes) - 0.2, max(c.lobes) + 1.2]);
    ylim (yl);
    set (gca, "xtick", c.lobes);
    xlabel ("lobes");
    ylabel (ylab);
    title (repro_method (m).label, "interpreter", "none");
    grid on;
  endfor
  repro_print (h, file, 90, "db_report");
endfunction

## positions for labels wanted at Y, at least GAP apart, within the limits YL
function ly = spread (y, gap, yl)
  [ys, o] = sort (y(:));
  n = numel (ys);
  for k = 2:n
    ys(k) = max (ys(k), ys(k-1) + gap);
  endfor
  top = yl(2) - gap / 2;
  if (n > 0 && ys(n) > top)
    ys(n) = top;
    for k = n-1:-1:1
      ys(k) = min (ys(k), ys(k+1) - gap);
    endfor
  endif
  ly = zeros (n, 1);
  ly(o) = ys;
endfunction

function write_gallery (c, D, P, F, E, H0)
  H = {"<!DOCTYPE html>", "<html><head><meta charset=\"utf-8\"><title>lafortune: contact sheets</title>", ...
       "<style>body{font-family:sans-serif} img{max-width:100%} .err{color:#a00}</style></head><body>", ...
       "<h1>Measured render and Lafortune fits, per material</h1>", "<ul>"};
  for i = 1:numel (D)
    H{end+1} = sprintf ("<li><a href=\"#%s\">%s</a>%s</li>", D(i).material, D(i).material,
                        ifelse (D(i).ok, "", " (failed)"));
  endfor
  H{end+1} = "</ul>";
  lobes = strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), "/");
  for i = 1:numel (D)
    H{end+1} = sprintf ("<h2 id=\"%s\">%s</h2>", D(i).material, D(i).material);
    if (! D(i).ok)
      H{end+1} = sprintf ("<p class=\"err\">%s</p>", html_escape (D(i).error));
      continue;
    endif
    for m = c.methods
      H{end+1} = sprintf (["<p>%s, %s lobes: in-sample (POV-Ray, the scene's light): PSNR %s dB; FLIP %s; " ...
                           "&Delta;E %s; <b>held out</b>: FLIP %s</p>"], repro_method (m{1}).label,
                          lobes, lobes_txt (P.(m{1})(i,:)), lobes_txt (F.(m{1})(i,:), "%.3f"),
                          lobes_txt (E.(m{1})(i,:)), lobes_txt (H0.(m{1})(i,:), "%.3f"));
    endfor
    H{end+1} = sprintf ("<img src=\"../%s/%s\" alt=\"%s\">", repro_files ("db_material", "", D(i).material),
                        D(i).rec.sheet.file, D(i).material);
    if (isfield (D(i).rec.sheet, "heldout_file") && ! isempty (D(i).rec.sheet.heldout_file))
      H{end+1} = sprintf ("<img src=\"../%s/%s\" alt=\"%s, held out\">", repro_files ("db_material", "", D(i).material),
                          D(i).rec.sheet.heldout_file, D(i).material);
    endif
  endfor
  H{end+1} = "</body></html>";
  repro_save (repro_files ("gallery", c.results, ""), [strjoin(H, "\n") "\n"]);
endfunction

function s = html_escape (s)
  s = strrep (strrep (strrep (s, "&", "&amp;"), "<", "&lt;"), ">", "&gt;");
endfunction

function s = ifelse (c, a, b)
  if (c) s = a; else s = b; endif
endfunction
