## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{rgb} =} img_tonemap (@var{img})
## @deftypefnx {lafortune} {[@var{rgb}, @var{stops}] =} img_tonemap (@var{img}, @var{exposure})
## Tone-map a linear HDR image to an 8-bit sRGB image for display.
##
## The same mapping as @code{img_write_png}: multiply by 2^@var{exposure}
## (stops, default 0; @qcode{"auto"} maps the 99th percentile of the
## luminance to 1), clamp to [0, 1], apply the sRGB transfer curve, round to
## @code{uint8}.  @var{stops} is the exposure applied.  Give the same
## exposure to images that are to be compared side by side.
##
## @example
## @group
## img = rt_render (scene_make ("sphere", "size", 64), merl_standin ("red-plastic"));
## [rgb, stops] = img_tonemap (img, "auto");
## image (rgb); axis image;
## @end group
## @end example
## @seealso{img_write_png, img_diff}
## @end deftypefn
function [rgb, stops] = img_tonemap (img, exposure = 0)
  if (nargin < 1 || nargin > 2)
    print_usage ();
  endif
  [rgb, stops] = tonemap (img, exposure, "img_tonemap");
endfunction

%!test
%! [rgb, s] = img_tonemap (0.5 * ones (2, 3, 3));
%! assert (class (rgb), "uint8");
%! assert (rgb(:)', uint8 (188 * ones (1, 18)));
%! assert (s, 0);
%! [rgb, s] = img_tonemap (0.25 * ones (2, 3, 3), "auto");
%! assert (s, 2);
%! assert (class (rgb), "uint8");
%! assert (rgb(1), uint8 (255));
%! assert (img_tonemap (cat (3, 0.5, 0.5, 0.5), -1), img_tonemap (cat (3, 0.25, 0.25, 0.25)));

%!error <Invalid call> img_tonemap ()
%!error id=lafortune:badImage img_tonemap (ones (2, 2))
%!error id=lafortune:badExposure img_tonemap (ones (2, 2, 3), "bright")
%!error <img_tonemap: EXPOSURE> img_tonemap (ones (2, 2, 3), NaN)
