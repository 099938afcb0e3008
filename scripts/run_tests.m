## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## run_tests: the test driver behind `make check`.
##
##   octave-cli scripts/run_tests.m TARBALL      install TARBALL into a scratch
##                                               prefix, load it, test it
##   octave-cli scripts/run_tests.m --path       test inst/ and src/ in place
##
## Runs every %!test / %!error / %!warning block of the package's functions
## (inst/*.m and the oct-files' src/*.cc tests) and of test/test_*.m, prints one
## line per file, the log of failing files, the number of tests skipped
## (their data or tool missing: Octave's own skips, and tests that print a
## line "skipped: why"), and last a line "N passed, M failed"; exits 1 on
## any failure.
##
## The files of SECOND (the longest, most of whose time is spent waiting for
## make, POV-Ray and the renders it starts) run in a second Octave process
## beside the others, so that make check uses both cores of a small machine:
##   octave-cli scripts/run_tests.m --worker LOCAL_LIST OUTDIR FILE...
## (LOCAL_LIST: the scratch prefix's package list, or "" for --path) writes
## OUTDIR/NAME.log, OUTDIR/NAME.res per file and OUTDIR/done last.

1;
## run one test file: its counts [n nmax nxfail nbug nskip nrtskip] and time.
## A test that finds its data or tool missing prints a line "skipped: why"
## and returns; it is counted as skipped (nrtskip), not passed, and its
## line is shown.
function [r, t] = run_file (name, log)
  fid = fopen (log, "w");
  t0 = tic ();
  try
    out = evalc ("[n, nmax, nxfail, nbug, nskip, nrtskip] = test (name, 'quiet', fid);");
  catch err
    fprintf (fid, "test driver error: %s\n", err.message);
    n = 0; nmax = 1; nxfail = nbug = nskip = nrtskip = 0;
    out = "";
  end_try_catch
  said = skip_lines (out);
  for i = 1:numel (said)
    printf ("     %s\n", said{i});
    fprintf (fid, "%s\n", said{i});
  endfor
  k = min (numel (said), n);
  n -= k;
  nrtskip += k;
  rest = regexprep (out, '^skipped:[^\n]*\n?', "", "lineanchors");
  if (! isempty (strtrim (rest)))      # what the tests print, after the file ran
    fprintf (fid, "%s", rest);
    printf ("%s", rest);
  endif
  fclose (fid);
  ## a file with no tests at all is a failure: every public file has tests
  if (nmax == 0)
    nmax = 1;
    fid = fopen (log, "a"); fprintf (fid, "no tests found\n"); fclose (fid);
  endif
  r = [n, nmax, nxfail, nbug, nskip, nrtskip];
  t = toc (t0);
endfunction

## the lines "skipped: why" that tests print in TXT
function said = skip_lines (txt)
  said = regexp (txt, '^skipped:[^\n]*', "match", "lineanchors");
endfunction

## add one file's counts R and time T to the totals, print its line
function [passed, failed, skipped, bad] = tally (short, r, t, txt, passed, failed, skipped, bad)
  nfail = r(2) - r(1) - r(3) - r(4) - r(5) - r(6);
  passed += r(1);
  failed += nfail;
  skipped += r(5) + r(6);
  skip = "";
  if (r(5) + r(6) > 0)
    skip = sprintf ("  (%d skipped)", r(5) + r(6));
  endif
  printf ("%-4s %-22s %3d/%-3d %6.1f s%s\n", merge (nfail == 0, "ok", "FAIL"), short,
          r(1), r(2), t, skip);
  fflush (stdout);
  if (nfail > 0)
    bad{end+1} = {short, txt};
  endif
endfunction

function short = short_name (name)
  [~, short] = fileparts (name);
endfunction

warning ("off", "Octave:shadowed-function");
here = fileparts (mfilename ("fullpath"));
top = fullfile (here, "..");
args = argv ();
if (isempty (args))
  error ("run_tests: give a package tarball or --path");
endif

## ---- the second process: run the files it was given, write their results
if (strcmp (args{1}, "--worker"))
  if (isempty (args{2}))
    addpath (fullfile (top, "inst"));
    addpath (fullfile (top, "src"));
  else
    pkg ("local_list", args{2});
    pkg ("load", "lafortune");
    warning ("off", "Octave:shadowed-function");
    pkg ("load", "optim");
  endif
  out = args{3};
  for k = 4:numel (args)
    short = short_name (args{k});
    [r, t] = run_file (args{k}, fullfile (out, [short ".log"]));
    fid = fopen (fullfile (out, [short ".res"]), "w");
    fprintf (fid, "%d ", r); fprintf (fid, "%.3f\n", t);
    fclose (fid);
  endfor
  fclose (fopen (fullfile (out, "done"), "w"));
  exit (0);
endif

scratch = tempname ();
mkdir (scratch);
if (strcmp (args{1}, "--path"))
  addpath (fullfile (top, "inst"));
  addpath (fullfile (top, "src"));
  local_list = "";
  printf ("run_tests: testing inst/ and src/ in place\n");
else
  tarball = args{1};
  local_list = fullfile (scratch, "octave_packages");
  pkg ("prefix", fullfile (scratch, "pkg"), fullfile (scratch, "pkg"));
  pkg ("local_list", local_list);
  printf ("run_tests: installing %s into a scratch prefix\n", tarball);
  fflush (stdout);
  pkg ("install", "-local", "-nodeps", tarball);
  pkg ("load", "lafortune");
  warning ("off", "Octave:shadowed-function");
  pkg ("load", "optim");
endif

## the package's functions (inst/ and its folders by area, not their
## private folders), found on the path by name; an internal function
## (__lafortune_x__, a helper several areas share, tested through the public
## ones as the private helpers are) only when it has test blocks of its own
names = {};
d = [glob(fullfile (top, "inst", "*.m")); glob(fullfile (top, "inst", "*", "*.m"))];
for k = 1:numel (d)
  [~, nm] = fileparts (d{k});
  if (! strncmp (nm, "__", 2) || ! isempty (regexp (fileread (d{k}), '(^|\n)%!(test|error|assert)', "once")))
    names{end+1} = nm;
  endif
endfor
d = dir (fullfile (top, "src", "*.cc"));
for k = 1:numel (d)
  [~, names{end+1}] = fileparts (d(k).name);
endfor
d = dir (fullfile (top, "test", "test_*.m"));
for k = 1:numel (d)
  names{end+1} = fullfile (top, "test", d(k).name);
endfor

## the second process's files
SECOND = {"test_reproduce", "test_pov"};
second = ismember (cellfun (@short_name, names, "uniformoutput", false), SECOND);
wdir = fullfile (scratch, "second");
mkdir (wdir);
if (any (second))
  octave = fullfile (OCTAVE_HOME (), "bin", "octave-cli");
  if (! exist (octave, "file"))
    octave = "octave-cli";
  endif
  q = @(s) ["'" strrep(s, "'", "'\\''") "'"];
  cmd = sprintf ("%s --no-gui --norc --no-history %s --worker %s %s %s > %s 2>&1 & echo $! > %s",
                 q(octave), q([mfilename("fullpath") ".m"]), q(local_list), q(wdir),
                 strjoin (cellfun (q, names(second), "uniformoutput", false), " "),
                 q(fullfile (wdir, "worker.out")), q(fullfile (wdir, "worker.pid")));
  system (cmd);
  printf ("run_tests: %s in a second Octave process\n",
          strjoin (cellfun (@short_name, names(second), "uniformoutput", false), ", "));
endif

passed = failed = skipped = 0;
bad = {};
t_all = tic ();
for k = find (! second)
  log = fullfile (scratch, sprintf ("test%03d.log", k));
  [r, t] = run_file (names{k}, log);
  [passed, failed, skipped, bad] = tally (short_name (names{k}), r, t, fileread (log),
                                          passed, failed, skipped, bad);
endfor
## the second process's results: wait while it runs (at most an hour more
## than this one took)
if (any (second))
  wpid = str2double (fileread (fullfile (wdir, "worker.pid")));
  for w = 1:3600
    if (exist (fullfile (wdir, "done"), "file") || system (sprintf ("kill -0 %d 2>/dev/null", wpid)) != 0)
      break;
    endif
    pause (1);
  endfor
  if (! exist (fullfile (wdir, "done"), "file"))   # still running after an hour
    system (sprintf ("kill %d 2>/dev/null", wpid));
  endif
  for k = find (second)
    short = short_name (names{k});
    res = fullfile (wdir, [short ".res"]);
    if (exist (res, "file"))
      v = str2num (fileread (res));
      said = skip_lines (fileread (fullfile (wdir, [short ".log"])));
      if (! isempty (said))
        printf ("     %s\n", said{:});
      endif
      [passed, failed, skipped, bad] = tally (short, v(1:6), v(7),
                                              fileread (fullfile (wdir, [short ".log"])),
                                              passed, failed, skipped, bad);
    else
      txt = "";
      if (exist (fullfile (wdir, "worker.out"), "file"))
        txt = fileread (fullfile (wdir, "worker.out"));
      endif
      [passed, failed, skipped, bad] = tally (short, [0 1 0 0 0 0], NaN,
                                              ["the second Octave process gave no result:\n" txt],
                                              passed, failed, skipped, bad);
    endif
  endfor
endif

for k = 1:numel (bad)
  printf ("\n---- failures in %s ----\n", bad{k}{1});
  lines = strsplit (bad{k}{2}, "\n");
  if (numel (lines) > 100)
    ## the failing block's head and end, and each failure's message (from
    ## "!!!!!" to its shared variables, which can be long)
    keep = false (size (lines));
    keep([1:30, end-59:end]) = true;
    for i = find (strncmp (lines, "!!!!!", 5))
      j = i + find (strncmp (lines(i+1:end), "shared variables", 16), 1);
      if (isempty (j))
        j = numel (lines) + 1;
      endif
      keep(i:min ([j, i + 40, numel(lines)])) = true;
    endfor
    out = {};
    i = 1;
    while (i <= numel (lines))
      if (keep(i))
        out{end+1} = lines{i};
        i++;
      else
        j = i + find (keep(i+1:end), 1) - 1;
        if (isempty (j))
          j = numel (lines);
        endif
        out{end+1} = sprintf ("[... %d lines ...]", j - i + 1);
        i = j + 1;
      endif
    endwhile
    lines = out;
  endif
  printf ("%s\n", strjoin (lines, "\n"));
endfor
confirm_recursive_rmdir (false);
rmdir (scratch, "s");
printf ("\ntotal test time %.0f s\n", toc (t_all));
if (skipped > 0)
  printf ("%d skipped\n", skipped);
endif
printf ("%d passed, %d failed\n", passed, failed);
exit (failed > 0);
