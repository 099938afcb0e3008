## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} repro_report ()
## Last step of `make reproduce`: RESULTS/summary.json, every number of the
## run (repro_summary: our numbers beside the paper's, the held-out
## verdicts, the best model of each material (MODELS, repro_models), fit
## errors and times, error against run time for fitting and rendering), and
## RESULTS/report.md, the template scripts/templates/report_reproduce.md
## (report_fill) filled from it (put in rows and words by repro_view).
## @end deftypefn
function repro_report ()
  c = repro_config ();
  if (! any (strcmp (c.methods, "inplane")))
    ## the paper's method is the report's first column and its reference
    error ("lafortune:badConfig",
           "repro_report: METHODS is '%s': make reproduce needs the paper's method, inplane",
           strjoin (c.methods, " "));
  endif
  sm = repro_summary (c);
  repro_save (repro_files ("report", c.results, ""), report_fill ("report_reproduce", repro_view (sm, c)));
  repro_save (repro_files ("summary", c.results, ""), sm);
  printf ("reproduce: wrote %s and %s\n", repro_files ("report", c.results, ""),
          repro_files ("summary", c.results, ""));
endfunction
