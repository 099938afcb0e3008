## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Integration test of `make database` at tiny settings (24 x 12 pixels,
## 2 samples per pixel, 1 and 2 lobes) on a scratch folder of three files:
## the two MERL-format files of ../shared/data/merl-proxy (or, when absent,
## the built-in stand-ins written in MERL format) and a truncated file.
##   - the run is killed twice and restarted: it finishes, every material has
##     its rows, the truncated file one row naming the error;
##   - FLIP, Delta E (CIEDE2000) and hue beside PSNR for both renderers
##     (table.csv, report.md, summary.json), the pairs of fits PSNR and FLIP
##     rank differently, the verdict by FLIP, figures/flip-lobes.png;
##   - a rerun does no work and rewrites nothing;
##   - a change to inst/pov_render.m (make -W) re-runs only the fits' renders
##     and what follows, not the fits nor the measured-data renders;
##   - GNU parallel over "ssh hosts" (an ssh stand-in that runs the command
##     here) and the Slurm scripts (an sbatch stand-in that runs the jobs
##     here) give the same table as the local run.
## Run by `make check` (which sets LAFORTUNE_TOP).

%!function top = __top ()
%! top = getenv ("LAFORTUNE_TOP");
%! if (isempty (top))
%!   top = pwd ();
%! endif
%! assert (exist (fullfile (top, "Makefile"), "file") == 2, "run from the project's top folder");
%!endfunction

%!function [st, txt] = __make (top, db, merl, extra)
%! cmd = sprintf (["make --no-print-directory -C '%s' %s DB='%s' MERL_DIR='%s' QUICK=1 " ...
%!                 "SIZE='24 12' SPP=2 HEMI_SAMPLES=2000 LOBES='1 2' POV_AA=0 2>&1"],
%!                top, extra, db, merl);
%! [st, txt] = system (cmd);
%!endfunction

%!function T = __table (file)
%! ## the rows of table.csv without the time columns, for comparing runs
%! L = strsplit (strtrim (fileread (file)), "\n");
%! head = strsplit (L{1}, ",");
%! keep = cellfun ("isempty", regexp (head, "time", "once"));
%! T = {};
%! for i = 1:numel (L)
%!   f = regexp (L{i}, ',(?=(?:[^"]*"[^"]*")*[^"]*$)', "split");
%!   T(end+1,:) = f(keep);
%! endfor
%!endfunction

%!function __data (merl)
%! mkdir (merl);
%! proxy = getenv ("MERL_PROXY_DIR");
%! for m = {"green-metallic-paint", "red-plastic"}
%!   src = fullfile (proxy, [m{1} ".binary"]);
%!   if (! isempty (proxy) && exist (src, "file"))
%!     [err, msg] = symlink (src, fullfile (merl, [m{1} ".binary"]));
%!     assert (err, 0, msg);
%!   else
%!     merl_write (fullfile (merl, [m{1} ".binary"]), merl_standin (m{1}));
%!   endif
%! endfor
%! fid = fopen (fullfile (merl, "truncated.binary"), "w");
%! fwrite (fid, [90 180 360], "int32");
%! fwrite (fid, ones (1000, 1), "double");
%! fclose (fid);
%!endfunction

%!test
%! top = __top ();
%! out = tempname ();
%! merl = fullfile (out, "merl");
%! db = fullfile (out, "db");
%! pidf = fullfile (out, "make.pid");
%! unwind_protect
%!   mkdir (out);
%!   __data (merl);
%!   ## killed twice, at different points, then finished
%!   for t = [3 2]
%!     ## make in a process group of its own, whose id the shell writes down
%!     cmd = sprintf (["setsid sh -c 'echo $$ > \"$0\"; exec make --no-print-directory -C \"$1\" -j2 database " ...
%!                     "DB=\"$2\" MERL_DIR=\"$3\" QUICK=1 SIZE=\"24 12\" SPP=2 HEMI_SAMPLES=2000 " ...
%!                     "LOBES=\"1 2\" POV_AA=0' '%s' '%s' '%s' '%s' > '%s/kill.log' 2>&1 &"],
%!                    pidf, top, db, merl, out);
%!     assert (system (cmd), 0);
%!     pause (t);
%!     pid = str2double (fileread (pidf));
%!     assert (pid > 1);
%!     assert (system (sprintf ("kill -TERM -%d", pid)), 0);   # the run was still going
%!     pause (1);
%!     system (sprintf ("kill -KILL -%d 2>/dev/null", pid));
%!     ## nothing of it left running (zombies not yet reaped do not count)
%!     alive = sprintf ("ps -e -o pgid=,stat= | awk '$1 == %d && $2 !~ /Z/' | grep -q .", pid);
%!     for w = 1:50
%!       if (system (alive) != 0)
%!         break;
%!       endif
%!       pause (0.1);
%!     endfor
%!     assert (system (alive) != 0, "the killed run is still alive");
%!   endfor
%!   assert (! exist (fullfile (db, "table.csv"), "file"), "the killed runs should not have finished");
%!   [st, txt] = __make (top, db, merl, "-j2 database");
%!   assert (st, 0, txt);
%!   T = __table (fullfile (db, "table.csv"));
%!   ## the published fits (PUBLISHED) of both materials, where ../shared has them
%!   npub = 2 * (exist (fullfile (top, "..", "shared", "data", "ngan2005", "lafortune-1lobe.tsv"), "file") == 2);
%!   ## head, 2 materials x 3 methods x 2 lobe counts, the published fits, 1 error
%!   assert (rows (T), 1 + 2 * 3 * 2 + npub + 1);
%!   assert (nnz (strcmp (T(:,2), "ngan2005") & strcmp (T(:,3), "1")), npub);
%!   rep = fileread (fullfile (db, "report.md"));
%!   if (npub)
%!     assert (! isempty (regexp (rep, ["By FLIP the recommended 1-lobe fit \\(scene\\) is better than the " ...
%!                                      "published one on \\d of 2 materials with POV-Ray"])), rep);
%!   else
%!     printf ("skipped: the published fits of ../shared/data/ngan2005 (absent)\n");
%!   endif
%!   assert (nnz (strcmp (T(:,2), "scene")), 2 * 2);   # the recommended fit is a method
%!   k = strcmp (T(:,1), "truncated");
%!   assert (nnz (k), 1);
%!   assert (T{k,4}, "error");
%!   assert (! isempty (strfind (T{k,5}, "truncated")), T{k,5});
%!   assert (all (strcmp (T(! k & ! strcmp (T(:,1), "material"),4), "ok")));
%!   rep = fileread (fullfile (db, "report.md"));
%!   assert (! isempty (strfind (rep, "**truncated**: fit: merl_read")));
%!   ## each method's materials whose render falls with one more lobe
%!   assert (numel (regexp (rep, "; more lobes render worse: ")), 3);
%!   S = jsondecode (fileread (fullfile (db, "summary.json")));
%!   assert (isfield (S.methods.scene, "largest_flip_rise") && S.methods.scene.largest_flip_rise >= 0);
%!   ## every fit rendered by both renderers
%!   assert (isfield (S.methods.scene, "largest_flip_rise_rt") && S.methods.scene.largest_flip_rise_rt >= 0);
%!   assert (all (isfinite (S.psnr_rt.scene(isfinite (S.psnr.scene)))));
%!   assert (numel (strfind (rep, " (POV-Ray), ")), 3, rep);
%!   assert (numel (strfind (rep, " (rt_render).")), 3, rep);
%!   ## the summary: median PSNR, FLIP, Delta E, hue per method and lobe count
%!   assert (! isempty (regexp (rep, ["\\| in-plane \\(the paper's method\\) \\| 2 \\| \\d+\\.\\d\\d \\| " ...
%!                                    "\\d\\.\\d{3} \\| \\d+\\.\\d\\d \\| \\d+\\.\\d \\|"])), rep);
%!   ## FLIP, Delta E (CIEDE2000) and hue beside PSNR in table.csv, both renderers
%!   okr = strcmp (T(:,4), "ok");
%!   for q = {"flip", "deltae", "hue"}
%!     for r = {"pov", "rt"}
%!       col = find (strcmp (T(1,:), [q{1} "_" r{1}]));
%!       assert (numel (col), 1, [q{1} "_" r{1}]);
%!       v = str2double (T(okr,col));
%!       assert (numel (v), 2 * 3 * 2 + npub);
%!       assert (all (isfinite (v) & v >= 0 & (v <= 1 | ! strcmp (q{1}, "flip"))), [q{1} "_" r{1}]);
%!     endfor
%!   endfor
%!   assert (size (S.flip.scene), [3 2]);      # materials x lobe counts, as S.psnr
%!   assert (size (S.flip_rt.scene), [3 2]);
%!   assert (numel (strfind (rep, "FLIP")) > 10);
%!   ## the pairs of fits that PSNR and FLIP rank differently
%!   assert (! isempty (regexp (rep, ["PSNR and FLIP rank \\d+ of 30 pairs of fits of the same material " ...
%!                                    "differently \\(\\d+ %; \\d+ with FLIP apart by more than [\\d.]+\\), " ...
%!                                    "and \\d+ of 6 pairs of materials fitted by the same method"])), rep);
%!   assert (S.rank_disagreement.pov.within_pairs, 2 * 15);   # 2 materials, 6 fits each: 15 pairs
%!   assert (S.rank_disagreement.pov.across_pairs, 3 * 2);    # 3 methods x 2 lobe counts, 1 pair
%!   ## the recommended fit's FLIP rises, per renderer; the verdict by FLIP
%!   assert (! isempty (regexp (rep, ["The recommended fit \\(scene\\) renders worse by FLIP with one more " ...
%!                                    "lobe \\(FLIP up by more than [\\d.]+, FAIL_FLIP_DROP\\) on: .+ with " ...
%!                                    "POV-Ray; .+ with rt_render\\."])), rep);
%!   assert (! isempty (regexp (rep, "has FLIP above [\\d.]+ \\(FAIL_FLIP")), rep);
%!   ## the plots (3 panels) and a contact sheet (3 panels a row): not blank,
%!   ## with coloured lines or renders
%!   for f = {"figures/psnr-lobes.png", [560 1560 3]; "figures/flip-lobes.png", [560 1560 3]; ...
%!            "materials/red-plastic/sheet/red-plastic.png", [NaN 768 3]}'
%!     img = double (imread (fullfile (db, f{1})));
%!     sz = size (img);
%!     assert (isequal (sz(isfinite (f{2})), f{2}(isfinite (f{2}))), [f{1} ": " mat2str(sz)]);
%!     assert (std (img(:)) > 10, f{1});
%!     coloured = max (img, [], 3) - min (img, [], 3) > 60;
%!     assert (nnz (coloured) > 200, f{1});
%!   endfor
%!   for f = {"figures/psnr-lobes.png", "gallery/index.html", "summary.json", ...
%!            "materials/red-plastic/sheet/red-plastic.png", ...
%!            "materials/red-plastic/fit/red-plastic-hemisphere-2.json", ...
%!            "materials/green-metallic-paint/render/green-metallic-paint-inplane-1.exr"}
%!     assert (exist (fullfile (db, f{1}), "file") == 2, f{1});
%!   endfor
%!   ## every step record has the same head and reads with jsondecode
%!   F = jsondecode (fileread (fullfile (db, "materials", "red-plastic", "fit", "red-plastic.json")));
%!   assert ({F.material, F.step, F.status}, {"red-plastic", "fit", "ok"});
%!   assert (size (F.inplane.trace), [3 1]);
%!   assert (all (diff (mean (F.inplane.errors.inplane.rmse, 2)) <= 1e-12));
%!   ## a rerun does no work
%!   t0 = dir (fullfile (db, "table.csv")).datenum;
%!   [st, txt] = __make (top, db, merl, "-j2 database");
%!   assert (st, 0, txt);
%!   assert (isempty (regexp (txt, "fitting|rendering|POV-Ray|FAILED|database: \\d+ materials")), txt);
%!   assert (dir (fullfile (db, "table.csv")).datenum, t0);
%!   ## a change to lafortune_import (which only the fits' renders call) re-runs
%!   ## the fits' renders, not the fits nor the measured renders (make passes -W
%!   ## to no sub-make: ask for the table itself)
%!   [st, txt] = __make (top, db, merl, sprintf ("-W inst/lafortune_import.m -j2 '%s'", fullfile (db, "table.csv")));
%!   assert (st, 0, txt);
%!   assert (! isempty (regexp (txt, "\\[red-plastic\\] POV-Ray render")), txt);
%!   assert (isempty (regexp (txt, "fitting|rendering the measured")), txt);
%!   assert (isequal (__table (fullfile (db, "table.csv")), T));
%!
%!   ## GNU parallel over ssh hosts; the ssh stand-in runs the command here
%!   if (system ("command -v parallel >/dev/null 2>&1") != 0)
%!     printf ("skipped: the GNU parallel path: no 'parallel' (Debian package parallel)\n");
%!   else
%!     ssh = fullfile (out, "ssh-here");
%!     fid = fopen (ssh, "w");
%!     fputs (fid, ["#!/bin/bash\n# ssh stand-in: skip the options, log the host, run the command here\n" ...
%!                  "while [ $# -gt 0 ]; do case \"$1\" in -o|-p|-l|-i|-S) shift 2;; -*) shift;; *) break;; esac; done\n" ...
%!                  "echo \"$1\" >> \"$(dirname \"$0\")/hosts.log\"; shift\n" ...
%!                  "[ \"$1\" = -- ] && shift\nexec bash -c \"$*\"\n"]);
%!     fclose (fid);
%!     system (sprintf ("chmod 755 '%s'", ssh));
%!     hosts = fullfile (out, "hosts");
%!     fid = fopen (hosts, "w"); fputs (fid, "1/node-a\n1/node-b\n"); fclose (fid);
%!     db2 = fullfile (out, "db-parallel");
%!     [st, txt] = __make (top, db2, merl, sprintf ("database HOSTS='%s' PARALLEL_OPTS='--ssh %s'", hosts, ssh));
%!     assert (st, 0, txt);
%!     used = strsplit (strtrim (fileread (fullfile (out, "hosts.log"))), "\n");
%!     assert (numel (used) >= 3);   # every material went through an "ssh host"
%!     assert (all (ismember (used, {"node-a", "node-b"})));
%!     assert (isequal (__table (fullfile (db2, "table.csv")), T));
%!   endif
%!
%!   ## Slurm: the submit script with an sbatch stand-in that runs the jobs here
%!   bin = fullfile (out, "bin");
%!   mkdir (bin);
%!   fid = fopen (fullfile (bin, "sbatch"), "w");
%!   fputs (fid, ["#!/bin/bash\n# sbatch stand-in: runs the job (every array task in turn) here, now\n" ...
%!                "arr=; wrap=; script=\n" ...
%!                "while [ $# -gt 0 ]; do case \"$1\" in\n" ...
%!                "  --array=*) arr=${1#--array=};; --wrap) wrap=$2; shift;; --wrap=*) wrap=${1#--wrap=};;\n" ...
%!                "  -*) ;; *) script=$1; shift; break;; esac; shift; done\n" ...
%!                "export SLURM_SUBMIT_DIR=$PWD\n" ...
%!                "log=\"$SBATCH_LOG\"\n" ...
%!                "if [ -n \"$wrap\" ]; then echo \"merge: $wrap\" >> \"$log\"; bash -c \"$wrap\" >> \"$log\" 2>&1 || exit 1\n" ...
%!                "else for i in $(seq ${arr%-*} ${arr#*-}); do echo \"task $i\" >> \"$log\";\n" ...
%!                "  SLURM_ARRAY_TASK_ID=$i bash \"$script\" \"$@\" >> \"$log\" 2>&1 || exit 1; done; fi\n" ...
%!                "echo $RANDOM\n"]);
%!   fclose (fid);
%!   system (sprintf ("chmod 755 '%s'", fullfile (bin, "sbatch")));
%!   db3 = fullfile (out, "db-slurm");
%!   log = fullfile (out, "sbatch.log");
%!   cmd = sprintf (["cd '%s' && PATH='%s':$PATH SBATCH_LOG='%s' scripts/db_slurm_submit DB='%s' MERL_DIR='%s' " ...
%!                   "QUICK=1 SIZE='24 12' SPP=2 HEMI_SAMPLES=2000 LOBES='1 2' POV_AA=0 2>&1"],
%!                  top, bin, log, db3, merl);
%!   [st, txt] = system (cmd);
%!   assert (st, 0, [txt fileread(log)]);
%!   assert (! isempty (regexp (txt, "job array \\d+ \\(3 materials\\), merge job \\d+")), txt);
%!   L = fileread (log);
%!   assert (! isempty (strfind (L, "task 3")) && ! isempty (strfind (L, "merge: make")), L);
%!   assert (isequal (__table (fullfile (db3, "table.csv")), T));
%! unwind_protect_cleanup
%!   if (exist (pidf, "file"))     # a run this test started and could not stop
%!     system (sprintf ("kill -KILL -%d 2>/dev/null", str2double (fileread (pidf))));
%!   endif
%!   if (strncmp (out, tempdir (), numel (tempdir ())) && isfolder (out))
%!     confirm_recursive_rmdir (false, "local");
%!     rmdir (out, "s");
%!   endif
%! end_unwind_protect
