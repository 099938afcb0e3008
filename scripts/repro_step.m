## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} repro_step (@var{step}, @var{material})
## @deftypefnx {} {@var{file} =} repro_step ("output", @var{step}, @var{material})
## @deftypefnx {} {@var{file} =} repro_step ("output", @var{step}, @var{material}, @var{root})
## Run one per-material step of `make reproduce` / `make database` and write
## its record, RESULTS/STEPDIR/MATERIAL*.json, atomically (the Make target).
##
## Steps: @code{fit} (repro_fit), @code{render_measured}
## (repro_render_measured), @code{render_fits} (repro_render_fits),
## @code{spp} (repro_spp), @code{study} (repro_study) and @code{sheet}
## (db_sheet).  Every record has the
## same head, then the step's own fields:
##
## @example
## @{"material": "red-plastic", "step": "fit", "status": "ok", "error": "",
##  "time": 12.3, ...the step's fields...@}
## @end example
##
## With DATABASE=1 a step that fails (an unreadable or corrupt file, or a
## failed earlier step) writes a record with @code{"status": "error"} and
## the message in @code{"error"} and returns normally, so that the other
## materials go on and a rerun does not retry an unchanged input; otherwise
## the error stops the run.
## @end deftypefn
function out = repro_step (step, material, varargin)
  if (strcmp (step, "output"))
    if (nargin > 3)
      root = varargin{2};                 # a material's folder of make database
    else
      root = repro_config ().results;
    endif
    out = output_file (root, material, varargin{1});
    return;
  endif
  c = repro_config ();
  steps = struct ("fit", {{"repro_fit", {}}},
                  "render_measured", {{"repro_render_measured", {}}},
                  "render_fits", {{"repro_render_fits", {"fit", "render_measured"}}},
                  "spp", {{"repro_spp", {"render_measured"}}},
                  "study", {{"repro_study", {"render_measured", "render_fits"}}},
                  "sheet", {{"db_sheet", {"fit", "render_measured", "render_fits"}}});
  if (! isfield (steps, step))
    error ("lafortune:badStep", "repro_step: unknown step '%s': expected one of %s",
           step, strjoin (fieldnames (steps)', ", "));
  endif
  fn = steps.(step){1};
  up = steps.(step){2};
  rec = output_file (c.results, step, material);
  t0 = tic ();
  try
    for i = 1:numel (up)
      f = output_file (c.results, up{i}, material);
      if (! exist (f, "file"))
        error ("lafortune:upstreamFailed", "the %s step has no record %s", up{i}, f);
      endif
      u = jsondecode (fileread (f));
      if (! strcmp (u.status, "ok"))
        error ("lafortune:upstreamFailed", "%s", u.error);
      endif
    endfor
    R = feval (fn, material);
    head = struct ("material", material, "step", step, "status", "ok", "error", "",
                   "time", toc (t0));
    for f = fieldnames (R)'
      head.(f{1}) = R.(f{1});
    endfor
    R = head;
  catch err
    if (! c.database)
      rethrow (err);
    endif
    msg = err.message;
    if (! strcmp (err.identifier, "lafortune:upstreamFailed") && ! isempty (err.identifier))
      msg = sprintf ("%s (%s)", msg, err.identifier);
    endif
    R = struct ("material", material, "step", step, "status", "error", "error", msg,
                "time", toc (t0));
    printf ("database: [%s] %s: FAILED: %s\n", material, step, msg);
  end_try_catch
  repro_save (rec, R);
endfunction

function f = output_file (root, step, material)
  switch (step)
    case "fit"
      f = fullfile (root, "fit", [material ".json"]);
    case "render_measured"
      f = fullfile (root, "render", [material "-measured.json"]);
    case "render_fits"
      f = fullfile (root, "render", [material "-fits.json"]);
    case "spp"
      f = fullfile (root, "spp", [material ".json"]);
    case "study"
      f = fullfile (root, "study", [material ".json"]);
    case "sheet"
      f = fullfile (root, "sheet", [material ".json"]);
    otherwise
      error ("lafortune:badStep", "repro_step: unknown step '%s'", step);
  endswitch
endfunction
