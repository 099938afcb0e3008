## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {} plot_renders (@var{imgs}, @var{labels}, @var{psnr})
## @deftypefnx {lafortune} {} plot_renders (@var{imgs}, @var{labels}, @var{psnr}, @var{name}, @var{value}, @dots{})
## @deftypefnx {lafortune} {[@var{hf}, @var{hax}] =} plot_renders (@dots{})
## Renders of measured data and of fits side by side, each fit with an inset
## of its difference from the measured render and its PSNR, as the paper's
## Fig. 4 and 5.
##
## @var{imgs} is a cell of linear HDR images (H x W x 3, as @code{rt_render},
## @code{pov_render} or @code{exrread} give them): 1 x C for one material or
## scene, R x C for R of them (one row each; the rows may have different
## sizes, e.g. a sphere and the Happy Buddha).  Column 1 is the reference
## (the measured data's render), columns 2 to C the fits.  @var{labels}
## names the columns (a cell of C strings, or R x C).  @var{psnr} (R x
## (C-1), dB) is each fit's PSNR against its row's reference, as
## @code{img_psnr} gives it; NaN leaves it out.
##
## Every image of a row is tone-mapped with the reference's exposure
## (@code{img_tonemap}, "auto"), so that brightness differences show.  In the
## bottom-right corner (option @code{"corner"}) of each fit, framed in black
## and white, is the absolute
## difference from the reference (the mean over R, G, B of |fit - reference|,
## block-averaged), in false colour on the scale under the figure: black is
## no difference, white a difference of @code{"diff_scale"} times the
## reference's peak or more.  The caption under each fit gives its PSNR and,
## with the option @code{"paper"}, the paper's value.
##
## Options:
## @table @code
## @item "paper"
## R x (C-1) PSNR values of the paper, shown beside ours (NaN: none).
## @item "rows"
## names of the rows (cellstr of R), written at their left.
## @item "title"
## a heading for the figure.
## @item "diff_scale"
## the difference shown at full colour, as a fraction of the reference's
## peak (default 0.1).
## @item "inset"
## the inset's size as a fraction of the image's width and height (default
## 1/3).
## @item "corner"
## where the inset goes: @qcode{"southeast"} (default, bottom right),
## @qcode{"southwest"}, @qcode{"northeast"} or @qcode{"northwest"}.
## @item "width"
## the width of each image in pixels (default: 180 for tall images, 240
## for others).
## @item "map"
## what the inset shows: @qcode{"diff"} (default), the difference above;
## @qcode{"flip"}, the per-pixel HDR-FLIP error of @code{img_flip} (black 0,
## white 1: what a viewer sees as different), with the fit's FLIP (its mean
## over the object's pixels) in the caption under its PSNR.
## @item "file"
## a PNG file to write the figure to (atomically).
## @end table
##
## @example
## @group
## scene = scene_make ("sphere", "size", [128 64], "spp", 4);
## brdf = merl_standin ("red-plastic");
## models = @{lafortune_fit(merl_plane (brdf), 1), lafortune_fit(merl_plane (brdf), 2)@};
## ref = rt_render (scene, brdf);
## imgs = @{ref, rt_render(scene, models@{1@}), rt_render(scene, models@{2@})@};
## p = cellfun (@@(x) img_psnr (ref, x), imgs(2:end));
## plot_renders (imgs, @{"measured", "1 lobe", "2 lobes"@}, p, "paper", [28.12 27.56]);
## @end group
## @end example
## @seealso{img_psnr, img_tonemap, img_diff, rt_render, pov_render}
## @end deftypefn
function [hf, hax] = plot_renders (imgs, labels, psnr, varargin)
  fname = "plot_renders";
  if (nargin < 3)
    print_usage ();
  endif
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("paper", [], "rows", {{}}, "title", "",
                                             "diff_scale", 0.1, "inset", 1/3, "corner", "southeast",
                                             "width", [], "file", "", "map", "diff"));
  if (! iscell (imgs) || isempty (imgs) || ndims (imgs) > 2)
    error ("lafortune:badImage", "%s: IMGS must be a 1 x C or R x C cell of images", fname);
  endif
  [R, C] = size (imgs);
  for r = 1:R
    for c = 1:C
      x = imgs{r,c};
      if (! (isnumeric (x) && isreal (x) && ndims (x) == 3 && size (x, 3) == 3
             && ! isempty (x) && all (isfinite (x(:)))))
        error ("lafortune:badImage",
               "%s: IMGS{%d,%d} must be a finite H x W x 3 linear image, got %s %s",
               fname, r, c, class (x), mat2str (size (x)));
      endif
      if (! isequal (size (x), size (imgs{r,1})))
        error ("lafortune:badImage",
               "%s: IMGS{%d,%d} is %s but its row's reference is %s; a row's images must have one size",
               fname, r, c, mat2str (size (x)), mat2str (size (imgs{r,1})));
      endif
    endfor
  endfor
  if (iscellstr (labels) && numel (labels) == C)
    labels = repmat (labels(:).', R, 1);
  elseif (! (iscellstr (labels) && isequal (size (labels), [R C])))
    error ("lafortune:badOption", "%s: LABELS must be a cell of %d strings (or %d x %d)",
           fname, C, R, C);
  endif
  psnr = check_psnr (psnr, R, C, "PSNR", fname);
  paper = check_psnr (opt.paper, R, C, "PAPER", fname);
  rnames = opt.rows;
  if (! isempty (rnames) && ! (iscellstr (rnames) && numel (rnames) == R))
    error ("lafortune:badOption", "%s: ROWS must be a cell of %d strings", fname, R);
  endif
  ds = opt.diff_scale;
  if (! (isnumeric (ds) && isscalar (ds) && ds > 0 && isfinite (ds)))
    error ("lafortune:badOption", "%s: DIFF_SCALE must be a positive number", fname);
  endif
  fi = opt.inset;
  if (! (isnumeric (fi) && isscalar (fi) && fi > 0 && fi <= 0.5))
    error ("lafortune:badOption", "%s: INSET must be a fraction in (0, 0.5]", fname);
  endif
  if (! ischar (opt.title))
    error ("lafortune:badOption", "%s: TITLE must be a string", fname);
  endif
  if (! (ischar (opt.map) && any (strcmp (opt.map, {"diff", "flip"}))))
    error ("lafortune:badOption", "%s: MAP must be \"diff\" or \"flip\"", fname);
  endif
  flip = strcmp (opt.map, "flip");
  corners = {"southeast", "southwest", "northeast", "northwest"};
  if (! (ischar (opt.corner) && any (strcmp (opt.corner, corners))))
    error ("lafortune:badOption", "%s: CORNER must be one of %s", fname, strjoin (corners, ", "));
  endif

  ## panel sizes in pixels: one width for all, heights from each row's aspect
  asp = cellfun (@(x) rows (x) / columns (x), imgs(:,1));
  pw = opt.width;
  if (isempty (pw))
    pw = 240;
    if (max (asp) > 1.2)
      pw = 180;
    endif
  elseif (! (isnumeric (pw) && isscalar (pw) && pw >= 40))
    error ("lafortune:badOption", "%s: WIDTH must be at least 40 pixels", fname);
  endif
  ph = round (pw * asp);
  L = 20 + 25 * ! isempty (rnames);   # room for the row names
  G = 14;                             # between panels
  capt = 30;                          # the label above an image
  ## the PSNR below it (a line more for the paper's, and for FLIP)
  capb = 30 + 18 * ! isempty (paper) + 18 * flip;
  T = 10 + 28 * ! isempty (opt.title);
  Bar = 90;                           # the difference scale at the bottom
  W = L + C * pw + (C - 1) * G + 20;
  H = T + sum (ph + capt + capb) + Bar;
  hf = plot_begin (fname, [W H]);
  hax = zeros (R, C);
  cmap = hot (256);
  y = H - T;
  for r = 1:R
    fe = nan (1, C);
    y -= capt + ph(r);
    ref = double (imgs{r,1});
    [rgb1, stops] = img_tonemap (ref, "auto");
    peak = max (ref(:));
    if (! (peak > 0))
      peak = 1;
    endif
    for c = 1:C
      x = double (imgs{r,c});
      if (c == 1)
        rgb = double (rgb1) / 255;
      else
        rgb = double (img_tonemap (x, stops)) / 255;
        if (flip)
          [fe(c), d] = img_flip (ref, x);
        else
          d = mean (abs (x - ref), 3) / (ds * peak);
        endif
        rgb = add_inset (rgb, d, fi, cmap, opt.corner);
      endif
      ha = plot_place (hf, [L + (c - 1) * (pw + G), y, pw, ph(r)]);
      hax(r,c) = ha;
      image (ha, rgb);
      set (ha, "xtick", [], "ytick", [], "xlim", [0.5 columns(x)+0.5],
           "ylim", [0.5 rows(x)+0.5], "box", "on");
      title (ha, labels{r,c}, "interpreter", "none");
      cx = L + (c - 1) * (pw + G) + pw / 2;
      if (c == 1)
        plot_label (hf, cx, y - 4, "reference");
      elseif (! isnan (psnr(r,c-1)))
        plot_label (hf, cx, y - 4, sprintf ("PSNR %.2f dB", psnr(r,c-1)));
      endif
      yl = y - 22;
      if (! isempty (paper) && c > 1 && ! isnan (paper(r,c-1)))
        plot_label (hf, cx, yl, sprintf ("(paper %.2f dB)", paper(r,c-1)));
        yl -= 18;
      endif
      if (flip && c > 1)
        plot_label (hf, cx, yl, sprintf ("FLIP %.3f", fe(c)));
      endif
      if (c == 1 && ! isempty (rnames))
        ylabel (ha, rnames{r}, "interpreter", "none", "fontweight", "bold");
      endif
    endfor
    y -= capb;
  endfor
  w = min (W - 40, 420);
  if (flip)
    plot_cbar (hf, [(W - w) / 2, 64, w, 12], cmap, [0 1], "", [0 0.5 1], {"0", "0.5", "1"});
    plot_label (hf, W / 2, 26, "insets: HDR-FLIP error per pixel (0: no visible difference, 1: the largest)");
  else
    plot_cbar (hf, [(W - w) / 2, 64, w, 12], cmap, [0 ds], "", [0 ds/2 ds],
               {"0", sprintf("%g", ds/2), sprintf(">= %g", ds)});
    plot_label (hf, W / 2, 26, "insets: |fit - reference|, mean of R, G, B, as a fraction of the reference's peak");
  endif
  if (! isempty (opt.title))
    plot_heading (hf, opt.title);
  endif
  plot_save (hf, opt.file, fname);
endfunction

function p = check_psnr (p, R, C, what, fname)
  if (isempty (p))
    p = [];
    return;
  endif
  if (isvector (p) && R == 1)
    p = p(:).';
  endif
  if (! (isnumeric (p) && isreal (p) && isequal (size (p), [R C-1])))
    error ("lafortune:badOption", "%s: %s must be %d x %d numbers (dB; NaN: none), got %s",
           fname, what, R, C - 1, mat2str (size (p)));
  endif
  p = double (p);
endfunction

## the false-colour difference D (H x W, 1 = full colour), block-averaged,
## in a corner of RGB with a white frame
function rgb = add_inset (rgb, D, frac, cmap, corner)
  [H, W] = size (D);
  f = max (1, ceil (1 / frac));
  h = floor (H / f); w = floor (W / f);
  if (h < 3 || w < 3)
    return;
  endif
  B = reshape (D(1:h*f, 1:w*f), f, h, f, w);
  B = reshape (mean (mean (B, 1), 3), h, w);
  ins = plot_rgb (B, cmap, [0 1]);
  fr = max (1, round (min (H, W) / 256));   # frame: black outside, white inside
  F = 2 * fr;
  if (corner(1) == "s")                     # rows of the framed inset
    rr = H - h - 2 * F + 1 : H;
  else
    rr = 1 : h + 2 * F;
  endif
  if (strcmp (corner(6:end), "east"))
    cc = W - w - 2 * F + 1 : W;
  else
    cc = 1 : w + 2 * F;
  endif
  rgb(rr, cc, :) = 0;
  rgb(rr(fr+1:end-fr), cc(fr+1:end-fr), :) = 1;
  rgb(rr(F+1:F+h), cc(F+1:F+w), :) = ins;
endfunction

%!demo
%! scene = scene_make ("sphere", "size", [128 64], "spp", 4);
%! brdf = merl_standin ("red-plastic");
%! S = merl_plane (brdf, "step", 2);
%! [m, info, models] = lafortune_fit (S, 2);
%! ref = rt_render (scene, brdf, "progress", false);
%! imgs = {ref, rt_render(scene, models{1}, "progress", false), rt_render(scene, models{2}, "progress", false)};
%! p = cellfun (@(x) img_psnr (ref, x), imgs(2:end));
%! plot_renders (imgs, {"measured", "1 lobe", "2 lobes"}, p, "paper", [28.12 27.56],
%!               "title", "red-plastic (stand-in): sphere, rt_render");

%!shared d, ref, a, b
%! d = tempname (); mkdir (d);
%! [X, Y] = meshgrid (linspace (-1, 1, 64), linspace (-1, 1, 128));
%! s = max (1 - X.^2 - (Y / 2).^2, 0);
%! ref = cat (3, s, 0.5 * s, 0.2 * s);
%! a = 1.1 * ref;
%! b = ref; b(20:30, 20:30, :) += 0.3;

%!test
%! f = fullfile (d, "renders.png");
%! [hf, hax] = plot_renders ({ref, a, b; ref, b, a}, {"measured", "fit a", "fit b"}, [20 30; 31 21],
%!                           "paper", [29.27 31.44; NaN 27.56], "rows", {"one", "two"},
%!                           "title", "test", "file", f);
%! assert (size (hax), [2 3]);
%! close (hf);
%! info = imfinfo (f);
%! assert (info.Width, 45 + 3 * 180 + 2 * 14 + 20);
%! assert (info.Height, 38 + 2 * (360 + 30 + 48) + 90);
%! img = imread (f);
%! assert (numel (unique (img(:))) > 50);     # not blank
%! assert (nnz (any (img != 255, 3)) > 0.3 * rows (img) * columns (img));

%!test
%! ## a title too long for the figure is set smaller, all of it in the picture
%! t = repmat ("a long title, ", 1, 12);
%! hf = plot_renders ({ref, a}, {"measured", "fit a"}, 20, "title", t);
%! ht = findobj (hf, "type", "text", "string", t);
%! fs = get (ht, "fontsize");
%! close (hf);
%! assert (fs < 12 && fs >= 6);

%!test
%! ## tall images (the Happy Buddha's 256 wide x 512 high) keep their aspect
%! [hf, hax] = plot_renders ({zeros(512, 256, 3) + 0.1, zeros(512, 256, 3) + 0.2}, {"m", "f"}, 6.02);
%! p = get (hax(1), "position") .* [get(hf, "position")(3:4) get(hf, "position")(3:4)];
%! close (hf);
%! assert (p(4) / p(3), 2, 0.02);

%!test
%! ## the inset: bottom-right, framed, black where there is no difference
%! [hf, hax] = plot_renders ({ref, ref}, {"m", "same"}, Inf, "inset", 0.25);
%! c = get (findobj (hax(2), "type", "image"), "cdata");
%! close (hf);
%! assert (squeeze (c(end-5, end-5, :))', hot (256)(1,:));   # no difference
%! assert (squeeze (c(end, end-5, :))', [0 0 0]);            # the frame: black
%! assert (squeeze (c(end-1, end-5, :))', [1 1 1]);          # and white
%! assert (squeeze (c(end-34, end-5, :))', [1 1 1]);         # 32-row inset
%! assert (squeeze (c(end-35, end-5, :))', [0 0 0]);
%! assert (any (squeeze (c(end-36, end-5, :)) != 0));       # the image

%!test
%! ## the FLIP inset and caption
%! r0 = zeros (40, 30, 3); r0(10:30,8:22,:) = 0.5;
%! img = r0; img(10:30,8:22,1) = 0.8;
%! hf = plot_renders ({r0, img}, {"m", "redder"}, 20, "map", "flip");
%! unwind_protect
%!   t = findall (hf, "type", "text");
%!   s = get (t, "string");
%!   assert (any (strncmp (s, "FLIP 0.", 7)));
%!   assert (any (! cellfun (@isempty, strfind (s, "HDR-FLIP"))));
%! unwind_protect_cleanup
%!   close (hf);
%! end_unwind_protect

%!error <MAP must be> plot_renders ({ones(4,4,3), ones(4,4,3)}, {"a", "b"}, 1, "map", "delta")
%!error <Invalid call> plot_renders ({ref})
%!error id=lafortune:badImage plot_renders (ref, {"a"}, [])
%!error <a row's images must have one size> plot_renders ({ref, ref(1:10,:,:)}, {"a", "b"}, 1)
%!error id=lafortune:badOption plot_renders ({ref, a}, {"a"}, 1)
%!error <PSNR must be 1 x 1> plot_renders ({ref, a}, {"a", "b"}, [1 2])
%!error <PAPER must be 1 x 2> plot_renders ({ref, a, b}, {"a", "b", "c"}, [1 2], "paper", 3)
%!error id=lafortune:badOption plot_renders ({ref, a}, {"a", "b"}, 1, "diff_scale", 0)
%!error <CORNER must be one of> plot_renders ({ref, a}, {"a", "b"}, 1, "corner", "top")

%!test
%! ## the other corners
%! [hf, hax] = plot_renders ({ref, b, b, b}, {"m", "nw", "ne", "sw"}, [1 2 3], "inset", 0.25);
%! close (hf);
%! for k = 1:3
%!   cr = {"northwest", "northeast", "southwest"}{k};
%!   [hf, hax] = plot_renders ({ref, ref}, {"m", "f"}, 1, "inset", 0.25, "corner", cr);
%!   c = get (findobj (hax(2), "type", "image"), "cdata");
%!   close (hf);
%!   r = ifelse (cr(1) == "n", [2 18], [127 111]);
%!   q = ifelse (strcmp (cr(6:end), "east"), [64 55], [1 10]);
%!   assert (squeeze (c(r(1), q(2), :))', [1 1 1]);               # the frame
%!   assert (squeeze (c(r(2), q(2), :))', hot (256)(1,:));        # the inset
%! endfor

%!test
%! assert (strncmp (d, tempdir (), numel (tempdir ())));   # only our scratch folder
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
