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
## line per file, the log of failing files, and last a line
## "N passed, M failed"; exits 1 on any failure.

1;
function s = ifelse_str (c, a, b)
  if (c) s = a; else s = b; endif
endfunction

warning ("off", "Octave:shadowed-function");
here = fileparts (mfilename ("fullpath"));
top = fullfile (here, "..");
args = argv ();
if (isempty (args))
  error ("run_tests: give a package tarball or --path");
endif
scratch = tempname ();
mkdir (scratch);
if (strcmp (args{1}, "--path"))
  addpath (fullfile (top, "inst"));
  addpath (fullfile (top, "src"));
  printf ("run_tests: testing inst/ and src/ in place\n");
else
  tarball = args{1};
  pkg ("prefix", fullfile (scratch, "pkg"), fullfile (scratch, "pkg"));
  pkg ("local_list", fullfile (scratch, "octave_packages"));
  printf ("run_tests: installing %s into a scratch prefix\n", tarball);
  fflush (stdout);
  pkg ("install", "-local", "-nodeps", tarball);
  pkg ("load", "lafortune");
  warning ("off", "Octave:shadowed-function");
  pkg ("load", "optim");
endif

names = {};
d = dir (fullfile (top, "inst", "*.m"));
for k = 1:numel (d)
  [~, names{end+1}] = fileparts (d(k).name);
endfor
d = dir (fullfile (top, "src", "*.cc"));
for k = 1:numel (d)
  [~, names{end+1}] = fileparts (d(k).name);
endfor
d = dir (fullfile (top, "test", "test_*.m"));
for k = 1:numel (d)
  names{end+1} = fullfile (top, "test", d(k).name);
endfor

passed = failed = skipped = 0;
bad = {};
t_all = tic ();
for k = 1:numel (names)
  log = fullfile (scratch, sprintf ("test%03d.log", k));
  fid = fopen (log, "w");
  t0 = tic ();
  try
    [n, nmax, nxfail, nbug, nskip, nrtskip] = test (names{k}, "quiet", fid);
  catch err
    fprintf (fid, "test driver error: %s\n", err.message);
    n = 0; nmax = 1; nxfail = nbug = nskip = nrtskip = 0;
  end_try_catch
  fclose (fid);
  ## a file with no tests at all is a failure: every public file has tests
  if (nmax == 0)
    nmax = 1;
    fid = fopen (log, "a"); fprintf (fid, "no tests found\n"); fclose (fid);
  endif
  nfail = nmax - n - nxfail - nbug - nskip - nrtskip;
  passed += n;
  failed += nfail;
  skipped += nskip + nrtskip;
  [~, short] = fileparts (names{k});
  txt = fileread (log);
  printf ("%-4s %-22s %3d/%-3d %6.1f s\n", ifelse_str (nfail == 0, "ok", "FAIL"), short,
          n, nmax, toc (t0));
  fflush (stdout);
  if (nfail > 0)
    bad{end+1} = {short, txt};
  endif
endfor

for k = 1:numel (bad)
  printf ("\n---- failures in %s ----\n", bad{k}{1});
  lines = strsplit (bad{k}{2}, "\n");
  if (numel (lines) > 100)
    ## the failing block's message is at its end
    lines = [lines(1:30), {sprintf("[... %d lines ...]", numel (lines) - 90)}, lines(end-59:end)];
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

