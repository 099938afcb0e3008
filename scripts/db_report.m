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
## under each of them (@code{flip_heldout_LIGHT}), the noise floor of
## those verdicts (@code{flip_heldout_noise}: the FLIP between two renders
## of the measured data, the mean over the lights), errors (rmse, log rmse
## and cosine-weighted rmse as Ngan et al. 2005, means over R, G, B, on
## each method's table), fit time, render times, the model's size
## (@code{params}: the numbers it holds, @code{json_bytes}: its JSON
## file), its largest albedo (@code{albedo_max}, for the types brdf_fit
## reports it of) and its parameters (the columns of every type's fields); a
## material whose file could not be read or processed gets one row with
## status @code{error} and the message.
## @item report.md
## the template scripts/templates/report_database.md (report_fill) filled
## from the summary (db_summary, put in rows and words by db_view): the
## summary across materials (in-sample median PSNR, FLIP, ΔE and hue,
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
## the summary: every number report.md gives, for machines.
## @end table
## @end deftypefn
function db_report ()
  c = repro_config ();
  D = read_records (c);
  [sm, X] = db_summary (c, D);
  write_table (c, D, X);
  ## the plots: PSNR (in-sample) and FLIP (the verdicts') against lobe
  ## count, every material
  held = ! isempty (c.judge);
  plot_lobes_db (X.psnr.pov, c, c.materials, "in-sample PSNR against the measured render (dB), POV-Ray", [],
                 [], repro_files ("fig_psnr_lobes", c.results, ""));
  plot_lobes_db (X.flip.verdict, c, c.materials, merge (held, "held-out FLIP, mean over JUDGE's lights (lower is better)",
                                                          "in-sample FLIP, POV-Ray (lower is better)"), [0 1],
                 c.fail_flip, repro_files ("fig_flip_lobes", c.results, ""));
  repro_save (repro_files ("report", c.results, ""), report_fill ("report_database", db_view (sm)));
  repro_save (repro_files ("summary", c.results, ""), sm);
  write_gallery (c, D, X.psnr.pov, X.flip.pov, X.deltae.pov, X.flip.heldout, X.noise);
  printf ("database: %d materials (%d failed): %s\n", numel (c.materials), numel (sm.failed),
          repro_files ("report", c.results, ""));
endfunction

## every material's records (one per step of the database), whether all of
## its steps went well, and the first step's error where one did not
function D = read_records (c)
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
endfunction

## table.csv: one row per material, method and lobe count, and one per
## published fit; one row with the error for a material that failed
function write_table (c, D, X)
  mats = c.materials;
  nk = numel (c.lobes);
  nj = numel (c.judge);
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
          strcat("flip_heldout_", regexprep ({c.judge.name}, "[^A-Za-z0-9]+", "_")), {"flip_heldout_noise"}];
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
endfunction

## the held-out cells of table.csv of method M's fit at lobe slot J of
## material I: mean FLIP, dE, PSNR, hue over the NJ lights, then each
## light's FLIP, then the material's noise floor ("" without held-out
## lights or record)
function v = heldout_cells (X, m, i, j, nj)
  v = {X.flip.heldout.(m)(i,j), X.deltae.heldout.(m)(i,j), X.psnr.heldout.(m)(i,j), X.hue.heldout.(m)(i,j)};
  v = [v, num2cell(reshape (X.flip.light.(m)(i,j,:), 1, nj)), {X.noise(i)}];
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

## gallery/index.html: per material its sheets, each method's in-sample
## PSNR, FLIP, dE (P, F, E) and held-out FLIP H0, and the noise floor N0
## of the held-out verdicts
function write_gallery (c, D, P, F, E, H0, N0)
  H = {"<!DOCTYPE html>", "<html><head><meta charset=\"utf-8\"><title>lafortune: contact sheets</title>", ...
       "<style>body{font-family:sans-serif} img{max-width:100%} .err{color:#a00}</style></head><body>", ...
       "<h1>Measured render and Lafortune fits, per material</h1>", "<ul>"};
  for i = 1:numel (D)
    H{end+1} = sprintf ("<li><a href=\"#%s\">%s</a>%s</li>", D(i).material, D(i).material,
                        merge (D(i).ok, "", " (failed)"));
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
      H{end+1} = sprintf (["<p>Held out: the noise floor of these verdicts (FLIP between two renders of the " ...
                           "measured data, mean over the lights) is %.3f; fits closer than that tie.</p>"], N0(i));
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

function s = lobes_txt (v, fmt = "%.2f")
  s = strjoin (arrayfun (@(x) sprintf (fmt, x), v, "uniformoutput", false), " / ");
endfunction

