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
## one row per material, fit method and lobe count: PSNR, errors (rmse,
## log rmse and cosine-weighted rmse as Ngan et al. 2005, means over R, G,
## B, on each method's table), fit time, render times and the model's
## parameters; a material whose file could not be read or processed gets one
## row with status @code{error} and the message.
## @item report.md
## the summary across materials (median, worst and best PSNR per method and
## lobe count, the materials where the Lafortune model fails, times per
## stage) and the plot @file{figures/psnr-lobes.png}.
## @item gallery/index.html
## the contact sheets of all materials.
## @item summary.json
## the same numbers for machines.
## @end table
## @end deftypefn
function db_report ()
  c = repro_config ();
  mats = c.materials;
  steps = {"fit", "render_measured", "render_fits", "sheet"};
  label = struct ("inplane", "in-plane (the paper's method)",
                  "hemisphere", "hemisphere (solid-angle weights)",
                  "scene", "scene (the recommended fit)");
  D = struct ("material", mats, "ok", false, "error", "", "rec", []);
  for i = 1:numel (mats)
    root = fullfile (c.results, "materials", mats{i});
    rec = struct ();
    for s = steps
      f = repro_step ("output", s{1}, mats{i}, root);
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
  ## PSNR (materials x lobes) per method: P with POV-Ray, Q with rt_render
  P = Q = struct ();
  for m = c.methods
    P.(m{1}) = Q.(m{1}) = nan (numel (mats), nk);
    for i = ok
      P.(m{1})(i,:) = [D(i).rec.render_fits.(m{1}).psnr_pov];
      Q.(m{1})(i,:) = [D(i).rec.render_fits.(m{1}).psnr_rt];
    endfor
  endfor

  ## --- table.csv
  head = {"material", "method", "lobes", "status", "error", "psnr_db", "psnr_rt_db"};
  for t = c.methods
    head = [head, strcat({"rmse_", "log_rmse_", "cos_rmse_"}, t{1})];
  endfor
  head = [head, {"fit_time_s", "render_time_s", "measured_render_time_s", "rho_d_r", "rho_d_g", "rho_d_b"}];
  chn = "rgb";
  for j = 1:max (c.lobes)
    for p = {"cxy", "cz", "e"}
      for ch = 1:3
        head{end+1} = sprintf ("%s%d_%s", p{1}, j, chn(ch));
      endfor
    endfor
  endfor
  rows = {strjoin(head, ",")};
  for i = 1:numel (mats)
    if (! D(i).ok)
      rows{end+1} = csv_row ([{mats{i}, "", "", "error", D(i).error}, repmat({""}, 1, numel (head) - 5)]);
      continue;
    endif
    F = D(i).rec.fit;
    R = D(i).rec.render_fits;
    for m = c.methods
      r = F.(m{1});
      for j = 1:nk
        k = c.lobes(j);
        v = {mats{i}, m{1}, k, "ok", "", R.(m{1})(j).psnr_pov, R.(m{1})(j).psnr_rt};
        for t = c.methods
          e = r.errors.(t{1});
          v = [v, {mean(e.rmse(k,:)), mean(e.log_rmse(k,:)), mean(e.cos_rmse(k,:))}];
        endfor
        if (iscell (r.models))
          md = r.models{k};
        else
          md = r.models(k);
        endif
        v = [v, {max(r.lobe_time(k,:)), R.(m{1})(j).pov_time, D(i).rec.render_measured.info.time_total}, ...
             num2cell(md.rho_d(:)')];
        for l = 1:max (c.lobes)
          for p = {"Cxy", "Cz", "e"}
            if (l <= k)
              x = reshape (md.(p{1}), [], 3);
              v = [v, num2cell(x(l,:))];
            else
              v = [v, {"", "", ""}];
            endif
          endfor
        endfor
        rows{end+1} = csv_row (v);
      endfor
    endfor
  endfor
  repro_save (fullfile (c.results, "table.csv"), [strjoin(rows, "\n") "\n"]);

  ## --- the plot: PSNR against lobe count, every material
  fig = fullfile (c.results, "figures", "psnr-lobes.png");
  plot_psnr (P, c, mats, label, fig);

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
  L{end+1} = "PSNR: 10 log10 (peak^2 / MSE) of each fit's render against the measured-data render, peak = the measured render's maximum. Everything per row is in `table.csv`; the contact sheets are in `gallery/index.html`.";
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
  L{end+1} = sprintf (["PSNR with POV-Ray (the fits' renderer, as the paper used one) and, in the column rt_render, " ...
                       "with the Octave raytracer, which evaluates each model per sample (each against the measured " ...
                       "data rendered by the same renderer). The two renderers agree on the same model to %.1f dB " ...
                       "at worst, %.1f dB in the median over the %d fits."], min (ag), median (ag), numel (ag));
  L{end+1} = "";
  L{end+1} = "| method | lobes | median PSNR (dB) | worst PSNR (dB) | worst material | best PSNR (dB) | median PSNR, rt_render (dB) | median cosine-weighted rmse |";
  L{end+1} = "|---|---|---|---|---|---|---|---|";
  sm = struct ("materials", {mats}, "processed", numel (ok), "failed", {{}}, "methods", struct ());
  for m = c.methods
    for j = 1:nk
      x = P.(m{1})(ok,j);
      cr = arrayfun (@(i) mean (D(i).rec.fit.(m{1}).errors.(m{1}).cos_rmse(c.lobes(j),:)), ok);
      if (isempty (x))
        L{end+1} = sprintf ("| %s | %d | - | - | - | - | - | - |", label_of (label, m{1}), c.lobes(j));
        continue;
      endif
      [w, iw] = min (x);
      L{end+1} = sprintf ("| %s | %d | %.2f | %.2f | %s | %.2f | %.2f | %.4g |", label_of (label, m{1}), c.lobes(j),
                          median (x), w, mats{ok(iw)}, max (x), median (Q.(m{1})(ok,j)), median (cr));
      sm.methods.(m{1}).median_psnr(j) = median (x);
      sm.methods.(m{1}).median_psnr_rt(j) = median (Q.(m{1})(ok,j));
      sm.methods.(m{1}).worst_psnr(j) = w;
      sm.methods.(m{1}).worst_material{j} = mats{ok(iw)};
    endfor
  endfor
  L{end+1} = "";
  L{end+1} = "![PSNR against lobe count, every material](figures/psnr-lobes.png)";
  L{end+1} = "";
  L{end+1} = "## Where the Lafortune model fails";
  L{end+1} = "";
  L{end+1} = sprintf (["A material fails when its best render is below %g dB, or when going from %d to %d " ...
                       "lobes gains less than %g dB (the paper found this for red plastic). A method falls on a " ...
                       "material when one more lobe renders worse by more than %g dB (as the paper's 3-lobe fits did)."],
                      c.fail_psnr, min (c.lobes), max (c.lobes), c.fail_gain, c.fail_drop);
  L{end+1} = "";
  for m = c.methods
    best = max (P.(m{1})(ok,:), [], 2);
    gain = P.(m{1})(ok,end) - P.(m{1})(ok,1);
    low = ok(best < c.fail_psnr);
    flat = ok(gain < c.fail_gain & nk > 1);
    [falls, drop] = falls_of (P.(m{1}), ok, c.fail_drop);
    [falls_rt, drop_rt] = falls_of (Q.(m{1}), ok, c.fail_drop);
    L{end+1} = sprintf (["- %s: below %g dB: %s; more lobes do not help: %s; more lobes render worse: " ...
                         "%s (POV-Ray), %s (rt_render)."],
                        label_of (label, m{1}), c.fail_psnr, names_psnr (mats, low, max (P.(m{1})(low,:), [], 2)),
                        names_psnr (mats, flat, P.(m{1})(flat,end) - P.(m{1})(flat,1), " dB gain"),
                        names_psnr (mats, falls, -drop(drop > c.fail_drop), " dB"),
                        names_psnr (mats, falls_rt, -drop_rt(drop_rt > c.fail_drop), " dB"));
    sm.methods.(m{1}).fails_low = mats(low);
    sm.methods.(m{1}).fails_flat = mats(flat);
    sm.methods.(m{1}).falls = mats(falls);
    sm.methods.(m{1}).largest_drop = max ([drop; 0]);
    sm.methods.(m{1}).falls_rt = mats(falls_rt);
    sm.methods.(m{1}).largest_drop_rt = max ([drop_rt; 0]);
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
  L{end+1} = "## Every material";
  L{end+1} = "";
  hdr = "| material |";
  sep = "|---|";
  for m = c.methods
    hdr = [hdr sprintf(" %s PSNR, POV-Ray (rt_render), %s lobes (dB) |", m{1}, strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), "/"))];
    sep = [sep "---|"];
  endfor
  L{end+1} = [hdr " contact sheet |"];
  L{end+1} = [sep "---|"];
  for i = 1:numel (mats)
    if (! D(i).ok)
      L{end+1} = sprintf ("| %s | %s |", mats{i}, strjoin (repmat ({"failed"}, 1, nm + 1), " | "));
      continue;
    endif
    s = sprintf ("| %s |", mats{i});
    for m = c.methods
      s = [s " " lobes_txt(P.(m{1})(i,:)) " (rt_render " lobes_txt(Q.(m{1})(i,:)) ") |"];
    endfor
    L{end+1} = [s sprintf(" [sheet](materials/%s/%s) |", mats{i}, D(i).rec.sheet.file)];
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
  repro_save (fullfile (c.results, "report.md"), strjoin (L, "\n"));
  sm.psnr = P;
  sm.psnr_rt = Q;
  sm.settings = struct ("scene", scene.name, "width", scene.width, "height", scene.height,
                        "spp", scene.spp, "pov_antialias", c.pov_aa, "max_angle", c.max_angle,
                        "lobes", c.lobes, "methods", {c.methods}, "quick", c.quick);
  repro_save (fullfile (c.results, "summary.json"), sm);
  write_gallery (c, D, P, label);
  printf ("database: %d materials (%d failed): %s\n", numel (mats), numel (bad),
          fullfile (c.results, "report.md"));
endfunction

## The materials (indices into OK) whose PSNR X (materials x lobes) falls
## by more than LIMIT dB with one more lobe, and every material's largest
## fall DROP
function [falls, drop] = falls_of (X, ok, limit)
  drop = zeros (numel (ok), 1);
  if (columns (X) > 1)
    drop = max (-diff (X(ok,:), 1, 2), [], 2);
  endif
  falls = ok(drop > limit);
endfunction

function s = lobes_txt (v)
  s = strjoin (arrayfun (@(x) sprintf ("%.2f", x), v, "uniformoutput", false), " / ");
endfunction

function s = label_of (label, m)
  s = m;
  if (isfield (label, m))
    s = label.(m);
  endif
endfunction

function s = names_psnr (mats, idx, v, unit = " dB")
  if (isempty (idx))
    s = "none";
  else
    s = strjoin (arrayfun (@(j) sprintf ("%s (%.2f%s)", mats{idx(j)}, v(j), unit), 1:numel (idx),
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

function plot_psnr (P, c, mats, label, file)
  warning ("off", "Octave:gnuplot-graphics");
  graphics_toolkit ("gnuplot");
  nm = numel (c.methods);
  h = figure ("visible", "off", "position", [0 0 520 * nm 560]);
  ## the same PSNR axis for every method
  v = cell2mat (cellfun (@(m) P.(m)(:), c.methods(:), "uniformoutput", false));
  v = v(isfinite (v));
  yl = [0 50];
  if (! isempty (v))
    yl = [floor(min (v)) - 1, ceil(max (v)) + 1];
  endif
  for i = 1:nm
    m = c.methods{i};
    subplot (1, nm, i);
    X = P.(m);
    col = lines (rows (X));
    ## the names at the line ends, spread apart so that none overlaps
    ok = find (isfinite (X(:,end)))';
    ly = spread (X(ok,end), (yl(2) - yl(1)) * 11 / 460, yl);
    for q = 1:numel (ok)
      r = ok(q);
      plot (c.lobes, X(r,:), "-o", "linewidth", 1, "color", col(r,:));
      hold on;
      plot ([c.lobes(end), c.lobes(end) + 0.25], [X(r,end), ly(q)], "-", "color", col(r,:));
      text (c.lobes(end) + 0.3, ly(q), mats{r}, "fontsize", 7, "interpreter", "none",
            "color", col(r,:) * 0.8);
    endfor
    hold off;
    xlim ([min(c.lobes) - 0.2, max(c.lobes) + 1.2]);
    ylim (yl);
    set (gca, "xtick", c.lobes);
    xlabel ("lobes");
    ylabel ("PSNR against the measured render (dB)");
    title (label_of (label, m), "interpreter", "none");
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

function write_gallery (c, D, P, label)
  H = {"<!DOCTYPE html>", "<html><head><meta charset=\"utf-8\"><title>lafortune: contact sheets</title>", ...
       "<style>body{font-family:sans-serif} img{max-width:100%} .err{color:#a00}</style></head><body>", ...
       "<h1>Measured render and Lafortune fits, per material</h1>", "<ul>"};
  for i = 1:numel (D)
    H{end+1} = sprintf ("<li><a href=\"#%s\">%s</a>%s</li>", D(i).material, D(i).material,
                        ifelse (D(i).ok, "", " (failed)"));
  endfor
  H{end+1} = "</ul>";
  for i = 1:numel (D)
    H{end+1} = sprintf ("<h2 id=\"%s\">%s</h2>", D(i).material, D(i).material);
    if (! D(i).ok)
      H{end+1} = sprintf ("<p class=\"err\">%s</p>", html_escape (D(i).error));
      continue;
    endif
    for m = c.methods
      H{end+1} = sprintf ("<p>%s: %s dB for %s lobes</p>", label_of (label, m{1}),
                          strjoin (arrayfun (@(v) sprintf ("%.2f", v), P.(m{1})(i,:), "uniformoutput", false), " / "),
                          strjoin (arrayfun (@num2str, c.lobes, "uniformoutput", false), "/"));
    endfor
    H{end+1} = sprintf ("<img src=\"../materials/%s/%s\" alt=\"%s\">", D(i).material,
                        D(i).rec.sheet.file, D(i).material);
  endfor
  H{end+1} = "</body></html>";
  repro_save (fullfile (c.results, "gallery", "index.html"), [strjoin(H, "\n") "\n"]);
endfunction

function s = html_escape (s)
  s = strrep (strrep (strrep (s, "&", "&amp;"), "<", "&lt;"), ">", "&gt;");
endfunction

function s = ifelse (c, a, b)
  if (c) s = a; else s = b; endif
endfunction
