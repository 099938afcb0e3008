## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_trace (@var{info})
## @deftypefnx {lafortune} {} plot_trace (@var{info}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_trace (@dots{})
## Plot a fit's error against run time, per channel.
##
## @var{info} is the second output of @code{lafortune_fit} (its field
## @code{trace}, a 1 x 3 cell of K x 2 arrays [seconds, rmse], one per
## channel R, G, B; and, when present, @code{lobe_time} and @code{history},
## nlobes x 3, which mark where each lobe count was done), a 1 x 3 cell of
## traces alone, or a cell of several such fits (one panel each, all with
## the same axes).  A trace read back with @code{jsondecode} (a cell, or a 3
## x K x 2 array) is accepted too.  Each curve is the rmse (1/sr) of the
## best parameters found so far against the seconds since that channel's fit
## began, on log-log axes, drawn in the channel's colour; a circle marked
## @var{k} is where the @var{k}-lobe fit was done.
##
## Options:
## @table @code
## @item "names"
## the panels' titles (cellstr).
## @item "title"
## a heading for the figure.
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @example
## @group
## brdf = merl_standin ("red-plastic");
## [m, info] = lafortune_fit (merl_plane (brdf), 3);
## plot_trace (info, "names", @{"red-plastic, 3 lobes"@});
## @end group
## @end example
## @seealso{lafortune_fit, plot_plane}
## @end deftypefn
function [hf, hax] = plot_trace (info, varargin)
  fname = "plot_trace";
  if (nargin < 1)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("names", {{}}, "title", "", "file", ""));
  if (iscell (info) && ! isempty (info) && ! one_trace (info))
    fits = info(:).';
  else
    fits = {info};
  endif
  n = numel (fits);
  T = cell (n, 3);
  LT = cell (n, 1);
  HI = cell (n, 1);
  for i = 1:n
    [T(i,:), LT{i}, HI{i}] = read_fit (fits{i}, i, fname);
  endfor
  names = opt.names;
  if (isempty (names))
    names = repmat ({""}, 1, n);
  elseif (ischar (names) && n == 1)
    names = {names};
  elseif (! (iscellstr (names) && numel (names) == n))
    error ("lafortune:badOption", "%s: NAMES must be a cell of %d strings", fname, n);
  endif
  if (! ischar (opt.title))
    error ("lafortune:badOption", "%s: TITLE must be a string", fname);
  endif
  ## common axes
  tt = cell2mat (cellfun (@(x) x(:,1), T(:), "uniformoutput", false));
  ee = cell2mat (cellfun (@(x) x(:,2), T(:), "uniformoutput", false));
  tmin = 1e-3;
  tt = max (tt, tmin);
  ee = ee(ee > 0);
  decades = @(v) 10 .^ [floor(log10 (min (v))), ceil(log10 (max (v) * 1.01))];
  xl = decades (tt);
  if (isempty (ee))
    yl = [0.1 1];
  else
    yl = decades (ee);
  endif

  col = [0.85 0.1 0.1; 0.1 0.6 0.1; 0.15 0.25 0.9];
  pw = 360; ph = 280; L = 80; G = 70; B = 60; T0 = 40 + 28 * ! isempty (opt.title); K = 130;
  hf = plot_begin (fname, [L + n * pw + (n - 1) * G + K, B + ph + T0]);
  hax = zeros (1, n);
  for i = 1:n
    ha = plot_place (hf, [L + (i - 1) * (pw + G), B, pw, ph]);
    hax(i) = ha;
    for c = 1:3
      x = T{i,c};
      if (isempty (x))
        continue;
      endif
      loglog (ha, max (x(:,1), tmin), x(:,2), "-", "color", col(c,:), "linewidth", 1.5);
      hold (ha, "on");
      if (! isempty (LT{i}))
        for k = 1:rows (LT{i})
          px = max (LT{i}(k,c), tmin);
          py = HI{i}(k,c);
          loglog (ha, px, py, "o", "color", col(c,:), "markersize", 6);
          [~, top] = max (HI{i}(k,:));
          if (c == top)               # one number per lobe count, above the highest
            text (ha, px, py * 1.25, sprintf ("%d", k), "fontsize", 9,
                  "horizontalalignment", "center", "verticalalignment", "bottom");
          endif
        endfor
      endif
    endfor
    hold (ha, "off");
    set (ha, "xlim", xl, "ylim", yl);
    xlabel (ha, "seconds since the channel's fit began", "interpreter", "none");
    if (i == 1)
      ylabel (ha, "rmse of the best fit so far (1/sr)", "interpreter", "none");
    endif
    if (! isempty (names{i}))
      title (ha, names{i}, "interpreter", "none");
    endif
  endfor
  plot_key (hf, [L + n * pw + (n - 1) * G + 10, B + ph - 70, K - 10, 70], col,
            {"red", "green", "blue"});
  if (any (! cellfun (@isempty, LT)))
    x0 = L + n * pw + (n - 1) * G + 10 + (K - 10) / 2;
    plot_label (hf, x0, B + ph - 85, "circle k:", "fontsize", 9);
    plot_label (hf, x0, B + ph - 100, "k lobes done", "fontsize", 9);
  endif
  if (! isempty (opt.title))
    plot_heading (hf, opt.title);
  endif
  plot_save (hf, opt.file, fname);
endfunction

## true if X is one fit's traces: a 1 x 3 cell of K x 2 numeric arrays
function tf = one_trace (x)
  tf = iscell (x) && numel (x) == 3 && all (cellfun (@(t) isnumeric (t) && (isempty (t) || columns (t) == 2), x));
endfunction

function [T, lt, hi] = read_fit (f, i, fname)
  lt = hi = [];
  if (isstruct (f) && isscalar (f) && isfield (f, "trace"))
    if (isfield (f, "lobe_time") && isfield (f, "history")
        && isequal (size (f.lobe_time), size (f.history)) && columns (f.history) == 3)
      lt = f.lobe_time;
      hi = f.history;
    endif
    f = f.trace;
  endif
  if (isnumeric (f) && ndims (f) == 3 && size (f, 1) == 3 && size (f, 3) == 2)
    f = arrayfun (@(c) reshape (f(c,:,:), [], 2), 1:3, "uniformoutput", false);
  endif
  if (! one_trace (f))
    error ("lafortune:badOption",
           "%s: fit %d must be lafortune_fit's INFO (field trace) or a 1 x 3 cell of K x 2 [seconds, rmse] arrays",
           fname, i);
  endif
  T = f(:).';
endfunction

%!demo
%! brdf = merl_standin ("red-plastic");
%! [m, info] = lafortune_fit (merl_plane (brdf, "step", 2), 3);
%! plot_trace (info, "names", {"red-plastic (stand-in), in-plane, 1 to 3 lobes"});

%!shared d, info
%! d = tempname (); mkdir (d);
%! t = [0; 0.01; 0.1; 0.5; 2];
%! info = struct ("trace", {{[t, [1; 0.5; 0.2; 0.1; 0.05]], [t, [2; 1; 0.3; 0.2; 0.1]], [t, [1; 0.3; 0.1; 0.08; 0.07]]}},
%!                "lobe_time", [0.1 0.1 0.1; 2 2 2], "history", [0.2 0.3 0.1; 0.05 0.1 0.07]);

%!test
%! f = fullfile (d, "trace.png");
%! [hf, hax] = plot_trace ({info, info.trace}, "names", {"a", "b"}, "title", "test", "file", f);
%! assert (numel (hax), 2);
%! close (hf);
%! s = imfinfo (f);
%! assert ([s.Width s.Height], [80 + 2 * 360 + 70 + 130, 60 + 280 + 68]);
%! img = imread (f);
%! assert (numel (unique (img(:))) > 20);     # not blank
%! assert (nnz (any (img != 255, 3)) > 0.02 * rows (img) * columns (img));

%!test
%! ## the trace as jsondecode returns it (equal lengths: a 3 x K x 2 array)
%! tr = jsondecode (jsonencode (info.trace));
%! hf = plot_trace (tr);
%! close (hf);

%!error <Invalid call> plot_trace ()
%!error id=lafortune:badOption plot_trace (struct ("trace", 3))
%!error id=lafortune:badOption plot_trace (info, "names", {"a", "b"})

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
