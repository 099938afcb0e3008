## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} repro_material (@var{material}, @var{queue})
## Run the steps of one material that Make found out of date, in one Octave
## process: the steps named in the file @var{queue} (one per line, as the
## steps' Make rules wrote them), each once, in the order of repro_files's
## table of steps, each by repro_step (which writes its record).
##
## One process per material: optim is loaded once, the MERL file is read
## once (repro_merl), and what a step keeps for the next ones (the measured
## render's trace, repro_trace; the POV-Ray view's geometry, pov_cast's)
## serves them.  The queue is removed before the first step runs: a run
## stopped halfway leaves the steps not done without a record (each record
## is written last), and Make queues them again.
##
## @example
## repro_material ("red-plastic", "results/queue/red-plastic")
## @end example
## @end deftypefn
function repro_material (material, queue)
  if (nargin != 2 || ! ischar (material) || ! ischar (queue))
    print_usage ();
  endif
  if (! exist (queue, "file"))
    return;
  endif
  todo = strsplit (strtrim (fileread (queue)));
  unlink (queue);
  S = repro_files ().steps;
  bad = setdiff (todo, [{S.name}, {""}]);
  if (! isempty (bad))
    error ("lafortune:badStep", "repro_material: unknown step '%s' in %s: expected one of %s",
           bad{1}, queue, strjoin ({S.name}, ", "));
  endif
  for s = {S.name}
    if (any (strcmp (todo, s{1})))
      repro_step (s{1}, material);
    endif
  endfor
endfunction
