## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_database: `make database` end to end with 1 and with 2 jobs on the
## same materials, into fresh scratch folders: wall time per run, the
## speed-up from 1 to 2 jobs (target >= 1.8 on 2 cores; one job already
## renders with POV-Ray on all cores, so the table also gives one job with
## one POV-Ray thread, which is what make -j 2 runs twice), seconds per
## material, and the time per material by stage (median over the materials,
## from the steps' records).  Materials: every *.binary in BENCH_MERL_DIR
## (default: the MERL-format stand-ins in MERL_PROXY_DIR); settings: the
## defaults of config.mk, or what BENCH_MAKE_ARGS adds (e.g. "QUICK=1").
## Prints a table; not a test.  Run: make bench, or
##   octave-cli scripts/bench_database.m

1;
function s = ifelse_str (c, a, b)
  if (c) s = a; else s = b; endif
endfunction

function [wall, S] = run_db (top, merl, jobs, args)
  db = tempname ();
  cmd = sprintf ("make --no-print-directory -s -C '%s' -j%d database MERL_DIR='%s' DB='%s' %s > '%s.log' 2>&1",
                 top, jobs, merl, db, args, db);
  t0 = tic ();
  st = system (cmd);
  wall = toc (t0);
  if (st != 0)
    error ("bench_database: make database failed, see %s.log", db);
  endif
  S = jsondecode (fileread (fullfile (db, "summary.json")));
  confirm_recursive_rmdir (false, "local");
  rmdir (db, "s");
  unlink ([db ".log"]);
endfunction

here = fileparts (mfilename ("fullpath"));
addpath (here);                           # bench_data
top = fullfile (here, "..");
merl = getenv ("BENCH_MERL_DIR");
if (isempty (merl))
  merl = fileparts (bench_data ("red-plastic"));
endif
if (isempty (merl) || isempty (dir (fullfile (merl, "*.binary"))))
  printf ("bench_database: skipped: no *.binary files (set BENCH_MERL_DIR or MERL_PROXY_DIR)\n");
  return;
endif
args = getenv ("BENCH_MAKE_ARGS");
n = numel (dir (fullfile (merl, "*.binary")));
printf ("bench_database: %d materials from %s, settings: %s, %d cores\n", n, merl,
        ifelse_str (isempty (args), "config.mk defaults", args), nproc ());
system (sprintf ("make --no-print-directory -s -C '%s/src' > /dev/null", top));
[w1, S1] = run_db (top, merl, 1, args);
w1t = run_db (top, merl, 1, [args " POV_THREADS=1"]);
w2 = run_db (top, merl, 2, args);
printf ("\n| jobs | POV-Ray threads | wall time (s) | s per material | speed-up |\n|---|---|---|---|---|\n");
printf ("| 1 | all cores | %.1f | %.1f | 1.00 |\n", w1, w1 / n);
printf ("| 1 | 1 | %.1f | %.1f | %.2f |\n", w1t, w1t / n, w1 / w1t);
printf ("| 2 | 1 per job | %.1f | %.1f | %.2f (%.2f against 1 job, 1 thread) |\n", w2, w2 / n,
        w1 / w2, w1t / w2);
printf ("\nTime per material by stage, 1 job (median over materials, s; Octave start-up not included):\n\n");
printf ("| stage | median (s) | max (s) |\n|---|---|---|\n");
for f = fieldnames (S1.stage_time)'
  t = S1.stage_time.(f{1});
  printf ("| %s | %.1f | %.1f |\n", f{1}, median (t), max (t));
endfor
