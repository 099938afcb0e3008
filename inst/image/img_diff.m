## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{D} =} img_diff (@var{ref}, @var{img})
## @deftypefnx {lafortune} {[@var{D}, @var{scale}] =} img_diff (@var{ref}, @var{img}, @var{name}, @var{value}, @dots{})
## Difference image of @var{img} against @var{ref}, for figures.
##
## @var{ref} and @var{img} are @var{H} x @var{W} or @var{H} x @var{W} x 3
## linear images of the same size.  @var{D} is an @var{H} x @var{W} x 3 RGB
## image with values in [0, 1], ready for @code{imshow} or @code{imwrite}.
##
## Options:
## @table @asis
## @item @qcode{"mode"} (@qcode{"abs"})
## @qcode{"abs"}: grey level |@var{img} - @var{ref}| / @var{scale}, the
## absolute difference averaged over the channels (black: no difference,
## white: @var{scale} or more).  @qcode{"signed"}: false colour of
## d = mean over channels of (@var{img} - @var{ref}) / @var{scale}, clipped
## to [-1, 1]: white where d = 0, blending to red (1, 0, 0) where
## @var{img} is brighter (d = 1) and to blue (0, 0, 1) where it is darker
## (d = -1).
## @item @qcode{"scale"} ([]: automatic)
## The difference (in the images' units) shown at full strength.  The
## default is the largest absolute (channel-averaged) difference, or 1 for
## equal images; give the same value to several calls to make their figures
## comparable, e.g. 0.01 * max (@var{ref}(:)) for "1 % of the peak".
## @end table
##
## @var{scale} returns the scale used, for the figure's caption.
##
## @example
## @group
## ref = rt_render (scene, m, "jitter", false);
## img = pov_render (scene, m);
## [D, s] = img_diff (ref, img, "mode", "signed");
## imshow (D); title (sprintf ("img - ref, full colour at %.3g", s));
## @end group
## @end example
## @seealso{img_psnr, pov_render, rt_render}
## @end deftypefn
function [D, scale] = img_diff (ref, img, varargin)
  if (nargin < 2)
    print_usage ();
  endif
  fname = "img_diff";
  opt = __lafortune_parse_opts__ (varargin, fname, struct ("mode", "abs", "scale", []));
  if (! isnumeric (ref) || ! isnumeric (img) || ! isreal (ref) || ! isreal (img)
      || ! any (size (ref, 3) == [1 3]) || ndims (ref) > 3 || isempty (ref))
    error ("lafortune:badImage",
           "%s: REF and IMG must be real H x W or H x W x 3 numeric images", fname);
  endif
  if (! isequal (size (ref), size (img)))
    error ("lafortune:badImage", "%s: REF and IMG must have the same size, got %s and %s",
           fname, mat2str (size (ref)), mat2str (size (img)));
  endif
  if (! all (isfinite (ref(:))) || ! all (isfinite (img(:))))
    error ("lafortune:badImage", "%s: REF and IMG must be finite", fname);
  endif
  if (! ischar (opt.mode) || ! any (strcmp (opt.mode, {"abs", "signed"})))
    error ("lafortune:badOption", "%s: \"mode\" must be \"abs\" or \"signed\"", fname);
  endif
  d = double (img) - double (ref);
  if (strcmp (opt.mode, "abs"))
    d = mean (abs (d), 3);
  else
    d = mean (d, 3);
  endif
  scale = opt.scale;
  if (isempty (scale))
    scale = max (abs (d(:)));
    if (scale == 0)
      scale = 1;
    endif
  elseif (! isscalar (scale) || ! isnumeric (scale) || ! (scale > 0) || ! isfinite (scale))
    error ("lafortune:badOption", "%s: \"scale\" must be a positive finite scalar", fname);
  endif
  d = max (min (d / scale, 1), -1);
  if (strcmp (opt.mode, "abs"))
    D = repmat (d, [1 1 3]);
  else
    p = max (d, 0);
    n = max (-d, 0);
    D = cat (3, 1 - n, 1 - p - n, 1 - p);
  endif
endfunction

%!test
%! ref = zeros (2, 3, 3);
%! img = ref; img(1,2,:) = [0.3 0.6 0.9]; img(2,3,1) = -0.3;
%! [D, s] = img_diff (ref, img);
%! assert (s, 0.6, eps);
%! assert (size (D), [2 3 3]);
%! assert (D(:,:,1), [0 1 0; 0 0 1/6], eps);
%! assert (D(:,:,2), D(:,:,1));
%! assert (D(:,:,3), D(:,:,1));

%!test
%! ## a fixed scale clips; grey images work too
%! [D, s] = img_diff ([0 0], [2 -0.5], "scale", 1);
%! assert (s, 1);
%! assert (D, cat (3, [1 0.5], [1 0.5], [1 0.5]));

%!test
%! ## signed: white at zero, red brighter, blue darker
%! ref = ones (1, 3, 3);
%! img = ref + cat (3, [0 1 -0.5], [0 1 -0.5], [0 1 -0.5]);
%! D = img_diff (ref, img, "mode", "signed");
%! assert (squeeze (D(1,1,:))', [1 1 1]);
%! assert (squeeze (D(1,2,:))', [1 0 0]);
%! assert (squeeze (D(1,3,:))', [0.5 0.5 1]);

%!test
%! ## equal images: all black, scale 1
%! [D, s] = img_diff (rand (4, 4, 3), zeros (4, 4, 3) + 0.5, "scale", 10);
%! assert (all (D(:) >= 0 & D(:) <= 0.1));
%! [D, s] = img_diff (ones (2), ones (2));
%! assert (s, 1);
%! assert (D, zeros (2, 2, 3));

%!error <Invalid call> img_diff (1)
%!error <same size> img_diff (ones (2, 2, 3), ones (2, 3, 3))
%!error <H x W or H x W x 3> img_diff (ones (2, 2, 2), ones (2, 2, 2))
%!error <finite> img_diff ([1 NaN], [1 1])
%!error <"mode"> img_diff (1, 1, "mode", "ratio")
%!error <"scale"> img_diff (1, 1, "scale", -1)
%!error id=lafortune:badOption img_diff (1, 1, "colour", 1)
