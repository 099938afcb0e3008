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
## config.mk, or what BENCH_MAKE_ARGS adds (e.g. "QUICK=1").  Each version
## runs in the environment its own Makefile sets: the base without the
## variables this checkout's Makefile sets (LAFORTUNE_OWN_ENV).
## BENCH_BASE=none skips the base.  This checkout runs twice: with the held-out judging
## (JUDGE of config.mk) and without it (JUDGE=), so the judging's cost per
## material is measured in the same run.  Beside the stages, their floors:
## POV-Ray's own time for the same render with a constant pigment (alone,
## and as many at once as render_fits runs), and the BRDF evaluations of a
## stage at the compiled cores' rates measured here.  Prints tables; not a
## test.  Run: make bench, or
##   octave-cli scripts/bench_database.m

1;
function [wall, S] = run_db (top, merl, jobs, args, env)
  db = tempname ();
  cmd = sprintf ("%smake --no-print-directory -s -C '%s' -j%d database MERL_DIR='%s' DB='%s' %s > '%s.log' 2>&1",
                 env, top, jobs, merl, db, args, db);
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

## The floors of the stages for this checkout's default settings: a POV-Ray
## run of a sphere with a constant pigment (the same size and
## anti-aliasing; alone, and NFITS at once as render_fits runs them), and the
## BRDF evaluations a material's renders need (the judge step: the light
## samples rt_render evaluates for the measured data and every fit under
## each held-out light; the slice renders: their tables) at the compiled
## cores' rates, measured here
function F = floors (merl)
  c = repro_config ();
  F = struct ("size", c.size, "aa", c.pov_aa);
  nfits = numel (c.methods) * numel (c.lobes) + (! isempty (c.published) && exist (c.published, "file") == 2);
  F.nfits = nfits;
  d = tempname ();
  mkdir (d);
  W = c.size(2); H = c.size(1);
  fid = fopen (fullfile (d, "c.pov"), "w");
  fprintf (fid, ["camera { orthographic location <0, 0, -10> look_at <0, 0, 0> right x * %g up y * %g }\n", ...
                 "sphere { <0, 0, 0>, 0.9 pigment { rgb <0.5, 0.3, 0.2> } finish { ambient 1 diffuse 0 } }\n"], ...
           W / H * 2, 2);
  fclose (fid);
  args = sprintf ("+Ic.pov +Oc.exr +FE +W%d +H%d -D +GS -GR -GP +A0.0 +AM1 +R%d -J +WT1", W, H, c.pov_aa);
  t = zeros (1, 3);
  for i = 1:3
    t0 = tic ();
    system (sprintf ("cd '%s' && povray %s > /dev/null 2>&1", d, args));
    t(i) = toc (t0);
  endfor
  F.pov1 = median (t);
  run = "";
  for i = 1:nfits
    run = [run, sprintf("(povray %s +Oc%d.exr > /dev/null 2>&1) & ", args, i)];
  endfor
  t0 = tic ();
  system (sprintf ("cd '%s' && { %s wait; }", d, run));
  F.povn = toc (t0);
  confirm_recursive_rmdir (false, "local");
  rmdir (d, "s");
  ## the compiled cores' rates
  n = 2 ^ 20;
  X = [rand(n, 1), rand(n, 1), 2 * rand(n, 1) - 1];
  m = struct ("rho_d", [0.1 0.2 0.3], "Cxy", -[1 1 1; 0.5 0.5 0.5; 2 2 2], "Cz", [1 1 1; 0.6 0.6 0.6; 2 2 2],
              "e", [10 20 30; 3 3 3; 200 200 200]);
  wi = [sqrt(1 - X(:,1) .^ 2), zeros(n, 1), X(:,1)];
  wo = [-sqrt(1 - X(:,2) .^ 2), zeros(n, 1), X(:,2)];
  lafortune_eval (m, wi(1:100,:), wo(1:100,:));
  t0 = tic (); lafortune_eval (m, wi, wo); F.rate_laf = n / toc (t0);
  b = merl_read (fullfile (merl, dir (fullfile (merl, "*.binary"))(1).name));
  merl_eval (b, wi(1:100,:), wo(1:100,:));
  t0 = tic (); merl_eval (b, wi, wo); F.rate_merl = n / toc (t0);
  ## the judge step's evaluations: each held-out light's light samples, for
  ## the measured data and every fit
  ev = 0;
  ns = 0;
  for L = c.judge
    if (strcmp (L.type, "environment"))
      sc = repro_scene (c, "spp", c.judge_spp, "light", "environment", "map", L.map,
                        "light_samples", c.judge_samples);
      [~, info] = rt_render (sc, b, "progress", false);
      ev += info.evaluations;
    endif
  endfor
  bj = ev / F.rate_merl + nfits * ev / F.rate_laf;
  slice = prod ([128 64]);                 # rt_render's slice table
  F.fit = struct ("pov", "-", "brdf", "-", "what", "not counted (leasqr's evaluations)");
  F.render_measured = struct ("pov", sprintf ("%.1f", F.pov1), "brdf", sprintf ("%.3f", slice / F.rate_merl),
                              "what", "one POV-Ray render; rt_render's slice table of the measured data");
  F.render_fits = struct ("pov", sprintf ("%.1f (%.1f one after another)", F.povn, nfits * F.pov1),
                          "brdf", sprintf ("%.3f", nfits * slice / F.rate_laf),
                          "what", sprintf ("%d POV-Ray renders at once; %d slice tables", nfits, nfits));
  F.judge = struct ("pov", "-", "brdf", sprintf ("%.2f", bj),
                    "what", sprintf ("%.3g light samples under the environments, measured data and %d fits", ev, nfits));
  F.sheet = struct ("pov", "-", "brdf", "-", "what", "no render");
endfunction

here = fileparts (mfilename ("fullpath"));
addpath (here);                           # bench_data, repro_config, repro_scene
addpath (fullfile (here, "..", "inst"));
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
        merge (isempty (args), "config.mk defaults", args), nproc ());
## the versions: this checkout, and the base exported and built in scratch
V = struct ("name", {"this checkout", "this checkout, JUDGE= (no held-out judging)"}, "top", top,
            "args", {args, [args " JUDGE="]}, "env", "");
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
    ## the base in the environment its own Makefile sets: without the
    ## variables this checkout's Makefile set (LAFORTUNE_OWN_ENV)
    own = strsplit (strtrim (getenv ("LAFORTUNE_OWN_ENV")));
    own = own(! cellfun (@isempty, own));
    env = "";
    if (! isempty (own))
      env = ["env" sprintf(" -u %s", own{:}) " "];
    endif
    V(end+1) = struct ("name", sprintf ("base %s", base), "top", bt, "args", args, "env", env);
  endif
  system (sprintf ("make --no-print-directory -s -C '%s/src' > /dev/null", top));
  for v = 1:numel (V)
    printf ("bench_database: %s, 1 job\n", V(v).name);
    fflush (stdout);
    [V(v).w1, V(v).S] = run_db (V(v).top, merl, 1, V(v).args, V(v).env);
    printf ("bench_database: %s, %d jobs\n", V(v).name, jobs);
    fflush (stdout);
    V(v).wj = run_db (V(v).top, merl, jobs, V(v).args, V(v).env);
  endfor
unwind_protect_cleanup
  confirm_recursive_rmdir (false, "local");
  rmdir (scratch, "s");
end_unwind_protect

printf ("\n| version | jobs | wall time (s) | s per material | it / this checkout |\n|---|---|---|---|---|\n");
for v = 1:numel (V)
  printf ("| %s | 1 | %.1f | %.1f | %s |\n", V(v).name, V(v).w1, V(v).w1 / n,
          merge (v == 1, "", sprintf ("%.2f", V(v).w1 / V(1).w1)));
  printf ("| %s | %d | %.1f | %.1f | %s |\n", V(v).name, jobs, V(v).wj, V(v).wj / n,
          merge (v == 1, "", sprintf ("%.2f", V(v).wj / V(1).wj)));
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

## the floors beside the stages: what POV-Ray itself takes for the same
## render with a constant pigment, and the BRDF evaluations of a stage at
## the compiled cores' measured rates (this checkout's settings)
F = floors (merl);
printf ("\nFloors per material (this checkout's default settings; s):\n\n");
printf ("| stage | this checkout (1 job) | POV-Ray, constant pigment | BRDF evaluations at the compiled rate | what the floor counts |\n|---|---|---|---|---|\n");
for f = st
  if (! isfield (F, f{1}))
    continue;
  endif
  t = NaN;
  if (isfield (V(1).S.stage_time, f{1}))
    t = median (V(1).S.stage_time.(f{1}));
  endif
  printf ("| %s | %.1f | %s | %s | %s |\n", f{1}, t, F.(f{1}).pov, F.(f{1}).brdf, F.(f{1}).what);
endfor
printf ("\n(a POV-Ray run of a %d x %d constant-pigment sphere, anti-aliasing %d: %.2f s alone, %.2f s each for %d at once; ", ...
        F.size(2), F.size(1), F.aa, F.pov1, F.povn / F.nfits, F.nfits);
printf ("compiled rates: the Lafortune core %.3g evaluations/s (3 lobes, RGB), measured data (merl_eval) %.3g/s)\n", ...
        F.rate_laf, F.rate_merl);

printf ("\n100 materials, extrapolated from these runs:\n\n| version | %d cores, make -j%d | one 64-core Slurm node |\n|---|---|---|\n",
        nproc (), jobs);
for v = 1:numel (V)
  task = jobs * V(v).wj / n;                 # one material on about one core
  printf ("| %s | %.1f min | %.1f min |\n", V(v).name, 100 * V(v).wj / n / 60,
          ceil (100 / 64) * task / 60);
endfor
