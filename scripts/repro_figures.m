## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_figures ()
## Step 6 of `make reproduce`: the figures, PNG files in RESULTS/figures,
## drawn by the package's plot_* functions (headless: the gnuplot toolkit,
## print -dpngcairo).  This script only decides what goes in which figure:
## @itemize
## @item plane-MATERIAL.png (plot_plane; the paper's Fig. 2 and 3): in-plane
## data at theta_i = 30 degrees and the 1-, 2-, 3-lobe in-plane fits;
## @item renders-MATERIAL.png (plot_renders; Fig. 4 and 5): the measured
## render and the POV-Ray renders of the fits, one row per method of
## METHODS (in-plane: the paper's method, with the paper's PSNR; general:
## the recommended fit; scene: the fit for this very light, so in-sample),
## with FLIP-map insets, PSNR and FLIP;
## @item heldout-MATERIAL.png: the same under JUDGE's first light, which no
## fit was made for (repro_judge's rt_render renders), its title with the
## noise floor under that light (two renders of the measured data);
## @item polar-MATERIAL.png (plot_polar): data and the 3-lobe in-plane fit
## in the plane of incidence at theta_i = 15, 30, 45, 60 degrees (log radius:
## the grazing lobes would hide the others);
## @item slice-MATERIAL.png (plot_slice): the theta_h-theta_d image at
## phi_d = 90 degrees of the data and the in-plane fits;
## @item fit-trace.png (plot_trace): in-plane fit error against run time;
## @item study-MATERIAL.png, study-flip-MATERIAL.png: the study (STUDY): PSNR
## and FLIP against lobes, one panel per table, one line per weighting
## (plot_lobes);
## @item env-samples.png: FLIP of the measured render under the light probe
## ENV_MAP against run time, numbers the light samples per pixel (drawn
## here);
## @item spp.png: render PSNR against run time, one panel per material (drawn
## here: a small plot).
## @end itemize
## @end deftypefn
function repro_figures ()
  c = repro_config ();
  fd = fileparts (repro_files ("figures", c.results, ""));
  repro_mkdir (fd);
  nl = numel (c.lobes);
  lobe_names = arrayfun (@(k) sprintf ("%d lobe%s", k, merge (k > 1, "s", "")), c.lobes,
                         "uniformoutput", false);
  fits = cell (1, numel (c.materials));
  for i = 1:numel (c.materials)
    mat = c.materials{i};
    printf ("reproduce: [%s] figures\n", mat);
    fflush (stdout);
    b = merl_read (repro_files ("merl", c.data_dir, mat));
    models = cell (1, nl);
    for j = 1:nl
      models{j} = brdf_import ([repro_files("model", c.results, mat, "inplane", c.lobes(j)) ".json"]);
    endfor
    ## Fig. 2 / 3
    done (plot_plane (b, models, "theta_i", 30, "max_angle", c.max_angle,
                      "names", strcat (lobe_names, " fit"), "title", mat,
                      "file", repro_files ("fig_plane", c.results, mat)));
    ## BRDF Explorer's view and MERL's
    done (plot_polar ({b, models{end}}, [15 30 45 60], "scale", "log",
                      "names", {[mat ", measured"], sprintf("%s fit (in-plane)", lobe_names{end})},
                      "file", repro_files ("fig_polar", c.results, mat)));
    done (plot_slice ([{b}, models], 90, "names", [{"measured"}, strcat(lobe_names, " fit")],
                      "file", repro_files ("fig_slice", c.results, mat)));
    ## Fig. 4 / 5: every method's fits in the scene (in-sample for the
    ## scene fit), by POV-Ray, and under JUDGE's first light (held out), by
    ## rt_render
    ref = exrread ([repro_files("measured_pov", c.results, mat) ".exr"]);   # the fits' renderer and samples
    F = jsondecode (fileread (repro_files ("render_fits", c.results, mat)));
    renders_figure (c, mat, ref, @(m, k) repro_files ("fit_render", c.results, mat, m, k),
                    @(m, j) F.(m)(j).psnr_pov,
                    sprintf ("%s: POV-Ray, %d x %d, anti-aliasing %d x %d (the scene fit's own light: in-sample)",
                             mat, columns (ref), rows (ref), c.pov_aa, c.pov_aa),
                    repro_files ("fig_renders", c.results, mat), true);
    J = jsondecode (fileread (repro_files ("judge", c.results, mat)));
    if (! isempty (J.lights))
      ref = exrread ([repro_files("judge_measured", c.results, mat) ".exr"]);
      renders_figure (c, mat, ref, @(m, k) repro_files ("judge_render", c.results, mat, m, k),
                      @(m, j) J.(m)(j).psnr(1),
                      sprintf ("%s: held out, under %s (no fit was made for it), rt_render; noise FLIP %.3f",
                               mat, J.lights(1).label, noise (J)),
                      repro_files ("fig_heldout", c.results, mat), false);
    endif
    Fi = jsondecode (fileread (repro_files ("fit", c.results, mat)));
    ## the step's record: the traces as brdf_fit gives them (plot_trace
    ## reads them as jsondecode returns them)
    fits{i} = struct ("trace", {Fi.inplane.trace},
                      "lobe_time", Fi.inplane.lobe_time, "history", Fi.inplane.errors.inplane.rmse);
  endfor
  ## fit error against run time
  done (plot_trace (fits, "names", c.materials,
                    "title", sprintf ("In-plane fits, 1 to %d lobes: error against run time", max (c.lobes)),
                    "file", repro_files ("fig_trace", c.results, "")));
  ## render error against run time: light samples of an environment, and
  ## samples per pixel (the last figure: the target)
  cost_figure (c, repro_files ("fig_env", c.results, ""), @(ax, m, f) env_panel (c, ax, m, f));
  cost_figure (c, repro_files ("figures", c.results, ""), @(ax, m, f) spp_panel (c, ax, m, f));
  if (c.study)
    for i = 1:numel (c.materials)
      study_figure (c, c.materials{i}, repro_files ("fig_study", c.results, c.materials{i}), "psnr_a");
      study_figure (c, c.materials{i}, repro_files ("fig_study_flip", c.results, c.materials{i}), "flip_a");
    endfor
  endif
endfunction

## the study: PSNR (Q "psnr_a") or FLIP ("flip_a") against lobes, one panel
## per table, one line per weighting
function study_figure (c, mat, file, q)
  R = jsondecode (fileread (repro_files ("study", c.results, mat)));
  M = R.methods;
  tables = unique ({M.table}, "stable");
  weights = unique ({M.weight}, "stable");
  P = cell (1, numel (tables));
  for t = 1:numel (tables)
    P{t} = nan (numel (weights), max (c.lobes));
    for m = M(strcmp ({M.table}, tables{t}))'
      P{t}(strcmp (weights, m.weight),:) = m.(q)(:)';
    endfor
  endfor
  paper = repro_paper (c, mat);
  if (all (isnan (paper)) || ! strcmp (q, "psnr_a"))
    paper = [];                     # no dashed line and no key for it
  endif
  names = strrep (strrep (tables, "inplane", "in-plane table"), "hemisphere", "hemisphere table");
  names = strrep (names, "scene", "scene table");
  what = "PSNR";
  ylab = "PSNR against the measured render (dB)";
  if (strcmp (q, "flip_a"))
    what = "FLIP (lower is better)";
    ylab = "HDR-FLIP against the measured render";
  endif
  done (plot_lobes (P, weights, "paper", repmat ({paper}, 1, numel (tables)),
                    "highlight", find (strcmp (weights, "relative")), "panels", names, "ylabel", ylab,
                    "title", sprintf ("%s: %s of each fit's POV-Ray render in the scene (in-sample for the scene table), by table and weighting", mat, what),
                    "file", file));
endfunction

## a row of the renders' figure: its method's label (repro_method)
## The measured render REF and every method's fits (FILE (method, k), an
## EXR without its extension; PSNR (method, j)) in one figure with FLIP
## maps, titled TTL, into OUT (plot_renders); the paper's PSNR beside the
## in-plane row when PAPER (its scene, not a held-out light)
function renders_figure (c, mat, ref, file, psnr, ttl, out, paper_on)
  mths = c.methods;
  nm = numel (mths);
  nl = numel (c.lobes);
  imgs = repmat ({ref}, nm, 1);
  P = zeros (nm, nl);
  for r = 1:nm
    for j = 1:nl
      imgs{r,j+1} = exrread ([file(mths{r}, c.lobes(j)) ".exr"]);
      P(r,j) = psnr (mths{r}, j);
    endfor
  endfor
  paper = NaN (nm, nl);
  if (paper_on)
    paper(strcmp (mths, "inplane"),:) = repro_paper (c, mat);
  endif
  names = arrayfun (@(k) sprintf ("%d lobe%s", k, merge (k > 1, "s", "")), c.lobes,
                    "uniformoutput", false);
  done (plot_renders (imgs, [{"measured"}, names], P, "paper", paper, "map", "flip",
                      "rows", cellfun (@row_name, mths, "uniformoutput", false),
                      "width", min (256, max (180, columns (ref))),   # the paper's 256: 1:1
                      "title", ttl, "file", out));
endfunction

## the noise floor under the first light of judge record J (repro_judge:
## the FLIP between two renders of the measured data), NaN when it has none
function f = noise (J)
  f = NaN;
  if (isfield (J, "noise_flip") && ! isempty (J.noise_flip))
    f = J.noise_flip(1);
  endif
endfunction

function s = row_name (m)
  s = repro_method (m).label;
endfunction

function done (hf)
  close (hf);
endfunction

## error against run time, one panel per material (drawn here: a small
## plot), each panel drawn by DRAW (ax, material, first)
function cost_figure (c, file, draw)
  warning ("off", "Octave:gnuplot-graphics");
  vis = "on";
  if (isempty (getenv ("DISPLAY")))
    vis = "off";
  endif
  n = numel (c.materials);
  W = 80 + n * 400 + (n - 1) * 60 + 20;
  h = figure ("visible", vis, "position", [40 40 W 420], "color", "w");
  for i = 1:n
    ax = axes ("parent", h, "position", [(80 + (i - 1) * 460) / W, 60 / 420, 400 / W, 310 / 420]);
    draw (ax, c.materials{i}, i == 1);
  endfor
  repro_print (h, file, 90, "repro_figures");
endfunction

## FLIP against run time of the measured data under the environment light,
## numbers: light samples per pixel
function env_panel (c, ax, mat, first)
  P = jsondecode (fileread (repro_files ("spp", c.results, mat))).env;
  hold (ax, "on");
  col = [0.8 0.3 0.1; 0.2 0.6 0.2; 0.1 0.3 0.8];
  for k = 1:rows (P.by_time)
    loglog (ax, P.by_time(k,:), P.by_flip(k,:), "-o", "linewidth", 1.5, "color", col(k,:));
  endfor
  set (ax, "xscale", "log", "yscale", "log");
  for j = 1:numel (P.samples)
    text (ax, P.by_time(3,j) * 1.06, P.by_flip(3,j) * 1.04, sprintf ("%d", P.samples(j)), "fontsize", 9);
  endfor
  legend (ax, P.sampling, "location", "southwest");
  xlabel (ax, "render time (s); numbers: light samples per pixel");
  if (first)
    ylabel (ax, sprintf ("FLIP against %d samples (mis)", P.reference));
  endif
  title (ax, sprintf ("%s: measured data under %s", mat, P.map), "interpreter", "none");
endfunction

## render PSNR against run time, numbers: samples per pixel
function spp_panel (c, ax, mat, first)
  P = jsondecode (fileread (repro_files ("spp", c.results, mat)));
  semilogx (ax, P.time, P.psnr, "-o", "linewidth", 1.5);
  for j = 1:numel (P.spp)
    text (ax, P.time(j) * 1.06, P.psnr(j), sprintf ("%d", P.spp(j)), "fontsize", 9);
  endfor
  xlabel (ax, "render time (s); numbers: samples per pixel");
  if (first)
    ylabel (ax, sprintf ("PSNR against %d spp (dB)", c.spp));
  endif
  title (ax, sprintf ("%s: measured data, rt_render", mat), "interpreter", "none");
endfunction
