## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later
##
## Help texts that keep: an installed function's help and comments say what
## it does and how to call it.  Measured numbers (a PSNR in dB, "N times
## faster", "N to M times") belong in the README, NEWS, benchmarks or a
## test that asserts them, and an installed package has no ../shared to
## point to.

%!function [files, lines] = comment_lines ()
%!  ## every .m file of the package: its folder, its folders by area and
%!  ## their private folders (the installed package under make check), and
%!  ## their comment lines outside the test blocks
%!  d = fileparts (which ("__lafortune_write__"));
%!  files = [glob(fullfile (d, "*.m")); glob(fullfile (d, "*", "*.m"));
%!           glob(fullfile (d, "*", "private", "*.m"))];
%!  lines = cell (numel (files), 1);
%!  for i = 1:numel (files)
%!    t = strsplit (fileread (files{i}), "\n");
%!    t = t(! strncmp (t, "%!", 2));
%!    lines{i} = t(! cellfun (@isempty, regexp (t, '^\s*(#|%)', "once")));
%!  endfor
%!endfunction

%!function pat = patterns ()
%!  pat = {'\.\./shared', '[0-9] ?dB\>', '[0-9.]+ to [0-9.]+ times', 'times (faster|slower)'};
%!endfunction

%!test
%! [files, lines] = comment_lines ();
%! assert (numel (files) > 100, "found only %d files of the package", numel (files));
%! bad = {};
%! pat = patterns ();
%! for i = 1:numel (files)
%!   for p = pat
%!     hit = ! cellfun (@isempty, regexp (lines{i}, p{1}, "once"));
%!     for l = find (hit)
%!       bad{end+1} = sprintf ("%s: %s", files{i}, strtrim (lines{i}{l}));
%!     endfor
%!   endfor
%! endfor
%! assert (isempty (bad), "measured numbers or ../shared in help or comments:\n%s",
%!         strjoin (bad, "\n"));

%!test
%! ## the check finds what it looks for
%! t = {"## agree to 58 dB or better", "## 1.1 to 1.5 times as long", "## see ../shared/data", "## 10 times faster", "## fine"};
%! pat = patterns ();
%! n = 0;
%! for p = pat
%!   n += nnz (! cellfun (@isempty, regexp (t, p{1}, "once")));
%! endfor
%! assert (n, 4);
