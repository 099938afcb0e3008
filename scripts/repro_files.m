## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {@var{F} =} repro_files ()
## @deftypefnx {} {@var{f} =} repro_files (@var{kind}, @var{root}, @var{material})
## @deftypefnx {} {@var{f} =} repro_files (@var{kind}, @var{root}, @var{material}, @var{method}, @var{k})
## The one definition of the pipeline's steps and files (`make reproduce`,
## `make database`).  The Makefile takes them from build/deps.mk, which
## scripts/repro_deps.m writes from this table (FILE_KIND := pattern,
## UP_STEP := the steps a step reads, SCRIPT_STEP := its function); the
## steps, repro_step and the reports call this function.  Nothing else
## spells a file name of the pipeline.
##
## With no argument, @var{F} has @code{files} (a struct: kind -> pattern,
## relative to the results folder; @code{%} is the material, @code{@@M} the
## fit method, @code{@@K} the lobe count), @code{steps} (struct array: the
## per-material steps in their order, @code{name}, @code{script},
## @code{up}: the steps whose records it reads; the record's kind is the
## step's name; @code{reproduce}, @code{database}: whether the pipeline
## runs it; a step that reads no record reads the material's data, the
## settings and the mesh) and @code{jobs} (the scripts of the whole-run
## jobs).
##
## Otherwise @var{f} is the file of @var{kind} under @var{root} (a results
## folder: RESULTS, or a material's folder of make database) for
## @var{material} and, for a fit's files, @var{method} and @var{k}.  Kind
## @code{merl} is a MERL file in a folder of them (@var{root}: MERL_DIR or
## DATA_DIR).
## @end deftypefn
function out = repro_files (kind, root, material, method, k)
  persistent F;
  if (isempty (F))
    files = struct (
      ## inputs
      "merl", "%.binary",                         # in MERL_DIR or DATA_DIR
      "data", "data/%.binary",                    # make reproduce's copy
      "source", "data/%.source.json",             # where that copy came from
      "settings", "settings.json",
      ## the per-material steps' records (the Make targets), by step name
      "fit", "fit/%.json",
      "render_measured", "render/%-measured.json",
      "render_fits", "render/%-fits.json",
      "judge", "judge/%.json",
      "spp", "spp/%.json",
      "study", "study/%.json",
      "sheet", "sheet/%.json",
      ## what the steps write besides their records (+ extension)
      "model", "fit/%-@M-@K",                     # .json, .txt, .brdf
      "measured", "render/%-measured",            # rt_render: .exr, .png
      "measured_pov", "render/%-measured-pov",    # POV-Ray: .exr
      "fit_render", "render/%-@M-@K",             # POV-Ray: .exr, .png
      "judge_measured", "judge/%-measured",        # rt_render under JUDGE's first light: .exr
      "judge_render", "judge/%-@M-@K",            # the fits there: .exr
      "sheet_png", "sheet/%.png",
      "sheet_heldout_png", "sheet/%-heldout.png",
      ## figures of make reproduce (figures: the last one written, the target)
      "figures", "figures/spp.png",
      "fig_plane", "figures/plane-%.png",
      "fig_polar", "figures/polar-%.png",
      "fig_slice", "figures/slice-%.png",
      "fig_renders", "figures/renders-%.png",
      "fig_heldout", "figures/heldout-%.png",
      "fig_trace", "figures/fit-trace.png",
      "fig_env", "figures/env-samples.png",
      "fig_study", "figures/study-%.png",
      "fig_study_flip", "figures/study-flip-%.png",
      ## the reports
      "report", "report.md",
      "summary", "summary.json",
      ## make database: a material's folder, and the whole run's files
      "db_material", "materials/%",
      "materials", "materials.txt",
      "table", "table.csv",
      "gallery", "gallery/index.html",
      "fig_psnr_lobes", "figures/psnr-lobes.png",
      "fig_flip_lobes", "figures/flip-lobes.png");
    steps = struct ("name", {"fit", "render_measured", "render_fits", "judge", "spp", "study", "sheet"},
                    "script", {"repro_fit", "repro_render_measured", "repro_render_fits", ...
                               "repro_judge", "repro_spp", "repro_study", "db_sheet"},
                    "up", {{}, {}, {"fit", "render_measured"}, {"fit"}, {"render_measured"}, ...
                           {"render_measured", "render_fits"}, ...
                           {"fit", "render_measured", "render_fits", "judge"}},
                    "reproduce", {true, true, true, true, true, true, false},
                    "database", {true, true, true, true, false, false, true});
    F = struct ("files", files, "steps", steps,
                "jobs", {{"repro_settings", "repro_data", "repro_figures", "repro_report", ...
                          "db_report"}});
  endif
  if (nargin == 0)
    out = F;
    return;
  endif
  if (nargin != 3 && nargin != 5)
    print_usage ();
  endif
  if (! ischar (kind) || ! isfield (F.files, kind))
    error ("lafortune:badFile", "repro_files: unknown kind of file '%s': expected one of %s",
           num2str (kind), strjoin (fieldnames (F.files)', ", "));
  endif
  p = strrep (F.files.(kind), "%", material);
  if (nargin == 5)
    p = strrep (strrep (p, "@M", method), "@K", sprintf ("%d", k));
  elseif (any (p == "@"))
    error ("lafortune:badFile", "repro_files: a file of kind '%s' needs METHOD and K", kind);
  endif
  out = fullfile (root, p);
endfunction
