## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_lobes (@var{psnr}, @var{names})
## @deftypefnx {lafortune} {} plot_lobes (@var{psnr}, @var{names}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_lobes (@dots{})
## Plot the PSNR of renders against the number of lobes, one line per fit
## method: how a picture improves (or not) with more parameters.
##
## @var{psnr} is M x K (M methods, K lobe counts 1..K) or a cell of such
## matrices, one panel each (for example one per material, all with the
## same axes); @var{names} a cellstr of the M methods' names.  NaN values
## are left out.
##
## Options:
## @table @code
## @item "paper"
## 1 x K, or a cell with one per panel: a reference drawn as a dashed black
## line (the paper's PSNR).
## @item "highlight"
## indices of methods drawn with thick lines (a recommended method).
## @item "panels"
## titles of the panels (cellstr).
## @item "ylabel"
## the y axis's label (default: PSNR); for another measure, such as FLIP.
## @item "title"
## a heading for the figure.
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @example
## @group
## p = [24.1 39.5 39.2; 35.3 46.0 45.2; 42.6 49.3 49.6];
## plot_lobes (p, @{"in-plane, plain", "hemisphere, log", "scene, image"@},
##             "paper", [29.27 31.44 31.02], "highlight", 3);
## @end group
## @end example
## @seealso{plot_renders, plot_trace, brdf_error, merl_scene}
## @end deftypefn
function [hf, hax] = plot_lobes (psnr, names, varargin)
  fname = "plot_lobes";
  if (nargin < 2)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("paper", [], "highlight", [], "panels", {{}},
                                             "ylabel", "PSNR against the measured render (dB)",
                                             "title", "", "file", ""));
  if (! iscell (psnr))
    psnr = {psnr};
  endif
  n = numel (psnr);
  if (! all (cellfun (@(p) isnumeric (p) && isreal (p) && ndims (p) == 2 && ! isempty (p), psnr)))
    error ("lafortune:badInput", "%s: PSNR must be an M x K real matrix or a cell of them", fname);
  endif
  M = rows (psnr{1});
  K = columns (psnr{1});
  if (! all (cellfun (@(p) isequal (size (p), [M K]), psnr)))
    error ("lafortune:badInput", "%s: every panel's PSNR must be %d x %d", fname, M, K);
  endif
  if (! (iscellstr (names) && numel (names) == M))
    error ("lafortune:badInput", "%s: NAMES must be a cell of %d strings (one per method)",
           fname, M);
  endif
  paper = opt.paper;
  if (! iscell (paper))
    paper = repmat ({paper}, 1, n);
  endif
  if (numel (paper) != n || ! all (cellfun (@(p) isempty (p) || (isnumeric (p) && numel (p) <= K), paper)))
    error ("lafortune:badOption", "%s: PAPER must be empty, 1 x K, or a cell of %d of them", fname, n);
  endif
  hl = opt.highlight;
  if (! (isnumeric (hl) && all (hl(:) >= 1 & hl(:) <= M & hl(:) == fix (hl(:)))))
    error ("lafortune:badOption", "%s: HIGHLIGHT must hold method indices from 1 to %d", fname, M);
  endif
  panels = opt.panels;
  if (isempty (panels))
    panels = repmat ({""}, 1, n);
  elseif (! (iscellstr (panels) && numel (panels) == n))
    error ("lafortune:badOption", "%s: PANELS must be a cell of %d strings", fname, n);
  endif
  if (! ischar (opt.ylabel))
    error ("lafortune:badOption", "%s: YLABEL must be a string", fname);
  endif
  if (! ischar (opt.title))
    error ("lafortune:badOption", "%s: TITLE must be a string", fname);
  endif

  all_v = cell2mat (cellfun (@(p) p(:), psnr(:), "uniformoutput", false));
  all_v = [all_v; cell2mat(cellfun (@(p) p(:), paper(:), "uniformoutput", false))];
  all_v = all_v(isfinite (all_v));
  if (isempty (all_v))
    all_v = [0; 1];
  endif
  ## the y range on a round step: 5 (dB) for PSNR-sized values, tenths for
  ## values in [0, 1] such as FLIP
  st = 5;
  if (max (abs (all_v)) <= 1)
    st = 0.1;
  endif
  yl = [floor(min (all_v) / st) * st, ceil(max (all_v) / st + 1e-9) * st];
  col = lines (M);
  pw = 330; ph = 280; L = 75; G = 40; B = 55;
  K0 = 70 + 7.5 * max (cellfun (@numel, [names(:); {"the paper (dashed)"}]));
  T0 = 40 + 28 * ! isempty (opt.title);
  hf = plot_begin (fname, [L + n * pw + (n - 1) * G + K0, B + ph + T0]);
  hax = zeros (1, n);
  for i = 1:n
    ha = plot_place (hf, [L + (i - 1) * (pw + G), B, pw, ph]);
    hax(i) = ha;
    for m = 1:M
      lw = 1.2 + 1.8 * any (hl == m);
      plot (ha, 1:K, psnr{i}(m,:), "-o", "color", col(m,:), "linewidth", lw, "markersize", 4);
      hold (ha, "on");
    endfor
    if (! isempty (paper{i}))
      plot (ha, 1:numel (paper{i}), paper{i}, "--k", "linewidth", 1.5);
    endif
    hold (ha, "off");
    set (ha, "xlim", [0.8 K + 0.2], "xtick", 1:K, "ylim", yl);
    grid (ha, "on");
    xlabel (ha, "lobes");
    if (i == 1)
      ylabel (ha, opt.ylabel);
    endif
    if (! isempty (panels{i}))
      title (ha, panels{i}, "interpreter", "none");
    endif
  endfor
  kc = col;
  kl = names(:)';
  if (any (! cellfun (@isempty, paper)))
    kc = [kc; 0 0 0];
    kl{end+1} = "the paper (dashed)";
  endif
  plot_key (hf, [L + n * pw + (n - 1) * G + 10, B, K0 - 10, ph], kc, kl);
  if (! isempty (opt.title))
    plot_heading (hf, opt.title);
  endif
  plot_save (hf, opt.file, fname);
endfunction

%!test
%! f = [tempname() ".png"];
%! unwind_protect
%!   [hf, hax] = plot_lobes ({[30 35 36; 32 38 40], [28 29 30; 31 33 34]}, {"a", "b"},
%!                           "paper", {[29 31 31], []}, "highlight", 2,
%!                           "panels", {"one", "two"}, "title", "PSNR", "file", f);
%!   assert (numel (hax), 2);
%!   img = imread (f);
%!   assert (size (img, 1) > 300 && size (img, 2) > 800);
%!   assert (numel (unique (img(:))) > 10);       # not blank
%! unwind_protect_cleanup
%!   close (hf);
%!   if (exist (f, "file"))
%!     delete (f);
%!   endif
%! end_unwind_protect

%!test
%! ## NaN left out; one panel
%! hf = plot_lobes ([30 NaN 36], {"only"});
%! close (hf);

%!error <Invalid call> plot_lobes (1)
%!error id=lafortune:badInput plot_lobes ("x", {"a"})
%!error id=lafortune:badInput plot_lobes ([1 2 3], {"a", "b"})
%!error id=lafortune:badInput plot_lobes ({[1 2], [1 2 3]}, {"a"})
%!error id=lafortune:badOption plot_lobes ([1 2 3], {"a"}, "highlight", 2)
%!error id=lafortune:badOption plot_lobes ([1 2 3], {"a"}, "paper", [1 2 3 4])

%!demo
%! ## the paper's PSNR and three ways to fit green metallic paint (sphere scene)
%! p = [24.1 39.5 39.2; 35.3 46.0 45.2; 42.6 49.3 49.6];
%! plot_lobes (p, {"in-plane, plain (the paper)", "hemisphere, log", "scene, image"},
%!             "paper", [29.27 31.44 31.02], "highlight", 3, "title", "green-metallic-paint");
