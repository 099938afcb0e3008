## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## bench_database: `make database` end to end, before and after, in one run:
## this checkout and a base version (BENCH_BASE, default 910a12b, the last
## commit of 0.4.3, exported by git archive into a scratch folder and built
## there), each with 1 job and with N jobs (N = the cores, at least 2) on the same materials, into fresh
## scratch folders.  Prints the wall time per run, seconds per material, the
## ratio base / this checkout, the time per material by stage (median over
## the materials, from the steps' records), and the extrapolation to 100
## materials: on this machine with make -j N (N = its cores), and on one
## 64-core Slurm node (64 array tasks of one CPU at once; a task's time is
## taken from the N-job run, where each job has about one core).
## Materials: every *.binary in BENCH_MERL_DIR (default: the MERL-format
## stand-ins in MERL_PROXY_DIR); settings: the defaults of each version's
## config.mk, or what BENCH_MAKE_ARGS adds (e.g. "QUICK=1").  BENCH_BASE=none
## skips the base.  This checkout runs twice: with the held-out judging
## (JUDGE of config.mk) and without it (JUDGE=), so the judging's cost per
## material is measured in the same run.  Prints tables; not a test.  Run: make bench, or
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
jobs = max (nproc (), 2);
printf ("bench_database: %d materials from %s, settings: %s, %d cores\n", n, merl,
        ifelse_str (isempty (args), "config.mk defaults", args), nproc ());
## the versions: this checkout, and the base exported and built in scratch
V = struct ("name", {"this checkout", "this checkout, JUDGE= (no held-out judging)"}, "top", top,
            "args", {args, [args " JUDGE="]});
base = getenv ("BENCH_BASE");
if (isempty (base))
  base = "910a12b";
endif
scratch = tempname ();
mkdir (scratch);
unwind_protect
  if (! strcmp (base, "none"))
    bt = fullfile (scratch, "base");
    mkdir (bt);
    st = system (sprintf ("git -C '%s' archive '%s' | tar -x -C '%s' && make --no-print-directory -s -C '%s/src' > '%s/build.log' 2>&1",
                          top, base, bt, bt, scratch));
    if (st != 0)
      log = "";
      if (exist (fullfile (scratch, "build.log"), "file"))
        log = fileread (fullfile (scratch, "build.log"));
      endif
      error ("bench_database: cannot export and build %s: %s", base, log);
    endif
    V(end+1) = struct ("name", sprintf ("base %s", base), "top", bt, "args", args);
  endif
  system (sprintf ("make --no-print-directory -s -C '%s/src' > /dev/null", top));
  for v = 1:numel (V)
    printf ("bench_database: %s, 1 job\n", V(v).name);
    fflush (stdout);
    [V(v).w1, V(v).S] = run_db (V(v).top, merl, 1, V(v).args);
    printf ("bench_database: %s, %d jobs\n", V(v).name, jobs);
    fflush (stdout);
    V(v).wj = run_db (V(v).top, merl, jobs, V(v).args);
  endfor
unwind_protect_cleanup
  confirm_recursive_rmdir (false, "local");
  rmdir (scratch, "s");
end_unwind_protect

printf ("\n| version | jobs | wall time (s) | s per material | it / this checkout |\n|---|---|---|---|---|\n");
for v = 1:numel (V)
  printf ("| %s | 1 | %.1f | %.1f | %s |\n", V(v).name, V(v).w1, V(v).w1 / n,
          ifelse_str (v == 1, "", sprintf ("%.2f", V(v).w1 / V(1).w1)));
  printf ("| %s | %d | %.1f | %.1f | %s |\n", V(v).name, jobs, V(v).wj, V(v).wj / n,
          ifelse_str (v == 1, "", sprintf ("%.2f", V(v).wj / V(1).wj)));
endfor

printf ("\nTime per material by stage, 1 job (median over materials, s; Octave start-up not included):\n\n");
st = fieldnames (V(1).S.stage_time)';
for v = 2:numel (V)
  for f = fieldnames (V(v).S.stage_time)'
    if (! any (strcmp (st, f{1})))
      st{end+1} = f{1};
    endif
  endfor
endfor
printf ("| stage |%s\n|---|%s\n", sprintf (" %s |", V.name), repmat ("---|", 1, numel (V)));
for f = st
  printf ("| %s |", f{1});
  for v = 1:numel (V)
    if (isfield (V(v).S.stage_time, f{1}))
      printf (" %.1f |", median (V(v).S.stage_time.(f{1})));
    else
      printf (" - |");
    endif
  endfor
  printf ("\n");
endfor

printf ("\n100 materials, extrapolated from these runs:\n\n| version | %d cores, make -j%d | one 64-core Slurm node |\n|---|---|---|\n",
        nproc (), jobs);
for v = 1:numel (V)
  task = jobs * V(v).wj / n;                 # one material on about one core
  printf ("| %s | %.1f min | %.1f min |\n", V(v).name, 100 * V(v).wj / n / 60,
          ceil (100 / 64) * task / 60);
endfor
