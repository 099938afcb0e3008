## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} repro_step (@var{step}, @var{material})
## Run one per-material step of `make reproduce` / `make database` and write
## its record atomically (the Make target; file names and the steps'
## order: repro_files).
##
## Steps: @code{fit} (repro_fit), @code{render_measured}
## (repro_render_measured), @code{render_fits} (repro_render_fits),
## @code{judge} (repro_judge: every fit under the held-out lights of JUDGE),
## @code{spp} (repro_spp), @code{study} (repro_study) and @code{sheet}
## (db_sheet); a step reads the records of the steps it follows
## (repro_files's @code{up}) and fails when one of them failed.  Every record has the
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
function repro_step (step, material)
  c = repro_config ();
  S = repro_files ().steps;
  k = find (strcmp ({S.name}, step));
  if (isempty (k))
    error ("lafortune:badStep", "repro_step: unknown step '%s': expected one of %s",
           step, strjoin ({S.name}, ", "));
  endif
  fn = S(k).script;
  up = S(k).up;
  rec = repro_files (step, c.results, material);
  t0 = tic ();
  try
    for i = 1:numel (up)
      f = repro_files (up{i}, c.results, material);
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
