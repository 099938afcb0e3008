## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## img_flip against NVIDIA's reference implementation of FLIP (its C++
## tool, version 1.6) on the image pairs of ../shared/data/flip-ref, whose
## reference.tsv holds the tool's mean error over all pixels and the
## exposures it used.  Run from the package root with
##   addpath ("inst"); addpath ("src"); test ("test/test_flip.m")

%!function d = __flipref ()
%!  d = getenv ("MERL_PROXY_DIR");
%!  if (isempty (d))
%!    d = fullfile (pwd (), "..", "shared", "data", "flip-ref");
%!  else
%!    d = fullfile (fileparts (regexprep (d, '[\\/]+$', "")), "flip-ref");
%!  endif
%!  if (! exist (fullfile (d, "reference.tsv"), "file"))
%!    printf ("skipped: %s absent\n", d);
%!    d = "";
%!  elseif (! exist ("exrread"))
%!    printf ("skipped: exrread (src/) not on the path\n");
%!    d = "";
%!  endif
%!endfunction

## The rows of reference.tsv: args, then the numeric columns (mean,
## weighted median, q1, q3, max, start, stop, count; NaN where empty).
%!function [args, val] = __rows (d)
%!  txt = fileread (fullfile (d, "reference.tsv"));
%!  lines = strsplit (txt, "\n");
%!  lines = lines(! cellfun (@isempty, lines) & ! strncmp (lines, "#", 1)
%!                & ! strncmp (lines, "args\t", 5));
%!  args = cell (numel (lines), 1);
%!  val = NaN (numel (lines), 8);
%!  for i = 1:numel (lines)
%!    f = strsplit (lines{i}, "\t");
%!    args{i} = f{1};
%!    val(i,1:numel (f) - 1) = str2double (f(2:end));
%!  endfor
%!endfunction

## Read the pair of one row and turn the tool's arguments into options.
%!function [ref, test, opts] = __pair (d, args)
%!  a = strsplit (args, " ");
%!  arg = @(k) a{find (strcmp (a, k)) + 1};
%!  rf = fullfile (d, arg ("-r"));
%!  tf = fullfile (d, arg ("-t"));
%!  opts = {};
%!  if (any (strcmp (a, "-ppd")))
%!    opts = [opts, {"ppd", str2double(arg ("-ppd"))}];
%!  endif
%!  if (strcmp (rf(end-3:end), ".png"))
%!    ref = imread (rf);
%!    test = imread (tf);
%!    opts = [opts, {"ldr", true}];
%!  else
%!    ref = exrread (rf);
%!    test = exrread (tf);
%!    if (any (strcmp (a, "-cstart")))
%!      opts = [opts, {"start", str2double(arg ("-cstart")), ...
%!                     "stop", str2double(arg ("-cstop")), "exposures", str2double(arg ("-n"))}];
%!    endif
%!  endif
%!  ref = ref(:,:,1:3);
%!  test = test(:,:,1:3);
%!endfunction

%!test
%! ## every row: the mean over all pixels to 0.002, the largest pixel loosely
%! d = __flipref ();
%! if (isempty (d))
%!   return;
%! endif
%! [args, val] = __rows (d);
%! assert (numel (args) >= 14);
%! for i = 1:numel (args)
%!   [ref, test, opts] = __pair (d, args{i});
%!   [err, map, info] = img_flip (ref, test, opts{:});
%!   printf ("  %-72s mean %.6f (tool %.6f)  max %.4f (tool %.4f)\n", args{i},
%!           info.mean_all, val(i,1), max (map(:)), val(i,5));
%!   assert (info.mean_all, val(i,1), 0.002);
%!   assert (max (map(:)), val(i,5), 0.05);
%!   if (! isnan (val(i,6)))
%!     assert ([info.start info.stop info.exposures], val(i,6:8), 1e-3);
%!   endif
%! endfor

%!test
%! ## the rows with explicit exposures that are the object-pixel rule's: the
%! ## default exposures reproduce them and their mean (the tool's own rule
%! ## chose the synthetic pair's, which has no background: the same there)
%! d = __flipref ();
%! if (isempty (d))
%!   return;
%! endif
%! [args, val] = __rows (d);
%! n = numel (args);
%! rule = [find(cellfun (@isempty, strfind (args, "-cstart"))
%!              & cellfun (@isempty, strfind (args, ".png"))); (n-3:n)'];
%! assert (numel (rule), 6);
%! for i = rule'
%!   [ref, test, opts] = __pair (d, args{i});
%!   k = find (strcmp (opts, "start"));
%!   opts(k:k+5) = [];          # drop start, stop and exposures: the rule
%!   [err, map, info] = img_flip (ref, test, opts{:});
%!   assert ([info.start info.stop], val(i,6:7), 1e-3);
%!   assert (info.exposures, val(i,8));
%!   assert (info.mean_all, val(i,1), 0.002);
%! endfor

%!test
%! ## the renders: the default mask is the object and its neighbours, where
%! ## the error is pooled; the background adds zeros to the mean over all
%! d = __flipref ();
%! if (isempty (d))
%!   return;
%! endif
%! ref = exrread (fullfile (d, "rp-measured.exr"))(:,:,1:3);
%! test = exrread (fullfile (d, "rp-scene-3.exr"))(:,:,1:3);
%! [err, map, info] = img_flip (ref, test);
%! obj = any (ref != 0, 3) | any (test != 0, 3);
%! assert (err, mean (map(obj)), 1e-12);
%! assert (info.mean_all, mean (map(:)), 1e-12);
%! assert (err > 2 * info.mean_all);
%! assert (info.max, max (map(:)));
