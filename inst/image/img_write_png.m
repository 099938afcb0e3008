## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {} {} img_write_png (@var{file}, @var{img})
## @deftypefnx {} {} img_write_png (@var{file}, @var{img}, @var{exposure})
## @deftypefnx {} {@var{stops} =} img_write_png (@dots{})
## Write an 8-bit sRGB PNG preview of the linear HDR image @var{img}.
##
## @var{img} is an @var{H} x @var{W} x 3 real (@code{double} or
## @code{single}) array of linear RGB radiance, row 1 at the top.  The
## preview is made by
##
## @enumerate
## @item multiplying by 2^@var{exposure} (@var{exposure} in stops, default 0);
## @item clamping to [0, 1] (NaN becomes 0, +Inf 1);
## @item applying the sRGB transfer curve (IEC 61966-2-1, piecewise:
## 12.92 @var{c} for @var{c} <= 0.0031308, else
## 1.055 @var{c}^(1/2.4) - 0.055);
## @item rounding to @code{uint8} (0..255).
## @end enumerate
##
## With @var{exposure} = @qcode{"auto"} the exposure is chosen so that the
## 99th percentile of the luminance Y = 0.2126 R + 0.7152 G + 0.0722 B over
## the pixels with finite Y (nearest-rank: the value at position
## ceil (0.99 @var{N}) of the sorted Y) maps to 1, i.e.,
## @var{exposure} = -log2 (that percentile); when that percentile is not
## positive the exposure is 0.  The brightest 1% of the pixels thus clip.
##
## The PNG is always written, whatever the extension of @var{file}.  It is
## first written to a temporary file in the folder of @var{file} that is
## then renamed onto @var{file}, so a failed write never leaves a partial
## file and never destroys an existing one.
##
## The file is written with @code{imwrite}, which lets GraphicsMagick choose
## the PNG colour type: a gray image (R = G = B) is stored as a grayscale
## PNG, and one whose pixels are all 0 or 255 as a 1-bit PNG, which
## @code{imread} returns as a @code{logical} array.
##
## The optional output @var{stops} is the exposure that was applied (useful
## with @qcode{"auto"}).
##
## Errors have the identifiers @code{lafortune:badFile},
## @code{lafortune:badImage}, @code{lafortune:badExposure} and
## @code{lafortune:unwritable} (the file could not be written; an earlier file is left as it was).
##
## Example:
##
## @example
## @group
## img = 0.5 * ones (4, 6, 3);          # linear 0.5
## img_write_png ("preview.png", img);
## imread ("preview.png")(1, 1, :)(:)'
##   @result{} 188   188   188
## stops = img_write_png ("preview.png", img, "auto")
##   @result{} stops = 1
## @end group
## @end example
##
## @seealso{exrwrite, exrread, imwrite}
## @end deftypefn

function stops = img_write_png (file, img, exposure = 0)

  if (nargin < 2 || nargin > 3)
    print_usage ();
  endif

  if (! ischar (file) || ! isrow (file))
    error ("lafortune:badFile",
           "img_write_png: FILE must be a non-empty character string");
  endif
  [rgb, exposure] = tonemap (img, exposure, "img_write_png");

  __lafortune_write__ (file, "img_write_png", "file", @(tmp) imwrite (rgb, tmp, "png"));

  if (nargout > 0)
    stops = exposure;
  endif

endfunction


%!function check_id (id, fcn, varargin)
%!  try
%!    fcn (varargin{:});
%!  catch err
%!    assert (err.identifier, id);
%!    return;
%!  end_try_catch
%!  error ("expected an error with identifier %s", id);
%!endfunction

## Known values of the sRGB curve, clamping, NaN/Inf, orientation.
%!test
%! d = tempname ();
%! mkdir (d);
%! f = fullfile (d, "a.png");
%! unwind_protect
%!   img = zeros (2, 4, 3);
%!   img(:,:,1) = [0 0.5 1 2; -1 0.001 NaN Inf];
%!   img(:,:,2) = [0.5 0.5 0.5 0.5; 0.5 0.5 0.5 0.5];
%!   img(:,:,3) = [0.2 0.2 0.2 0.2; 0.0031308 0.04 0.8 0.2];
%!   img_write_png (f, img);
%!   x = imread (f);
%!   assert (class (x), "uint8");
%!   assert (size (x), [2 4 3]);
%!   assert (x(:,:,1), uint8 ([0 188 255 255; 0 3 0 255]));
%!   assert (x(:,:,2), uint8 (188 * ones (2, 4)));
%!   ## 0.2 -> 0.48453 -> 124; 0.0031308 -> 0.04045 -> 10;
%!   ## 0.04 -> 0.22092 -> 56; 0.8 -> 0.90633 -> 231.
%!   assert (x(:,:,3), uint8 ([124 124 124 124; 10 56 231 124]));
%!   lst = dir (d);
%!   assert ({lst.name}, {".", "..", "a.png"});
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

## Exposure in stops; single input; overwrite; returned stops.
%!test
%! f = [tempname() ".png"];
%! unwind_protect
%!   stops = img_write_png (f, 0.25 * ones (3, 2, 3), 1);
%!   assert (stops, 1);
%!   assert (imread (f), uint8 (188 * ones (3, 2, 3)));
%!   img_write_png (f, single (ones (3, 2, 3)), -1);
%!   assert (imread (f), uint8 (188 * ones (3, 2, 3)));
%!   img_write_png (f, ones (1, 5, 3), int8 (-8));
%!   assert (imread (f), uint8 (repmat (13, [1 5 3])));  # 2^-8 -> 13
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Exposure "auto": the 99th percentile of the luminance maps to 1.
%!test
%! f = [tempname() ".png"];
%! unwind_protect
%!   Y = reshape (1:200, 10, 20) / 50;
%!   img = repmat (Y, [1 1 3]);
%!   img(1, 1, :) = NaN;                  # ignored by the percentile,
%!   img(2, 1, :) = Inf;                  # leaving Y = (3:200)/50
%!   stops = img_write_png (f, img, "auto");
%!   ## 198 finite values, rank ceil (0.99*198) = 197 -> Y = 199/50.
%!   assert (stops, -log2 (199 / 50), 1e-12);
%!   x = imread (f);
%!   assert (x(9, 20, 1), uint8 (255));   # Y = 199/50 -> 1
%!   assert (x(10, 20, 1), uint8 (255));  # above: clipped
%!   assert (x(8, 20, 1), uint8 (254));   # 198/199 -> 0.99779
%!   assert (x(1, 2, 1), uint8 (66));     # 11/199 -> 0.26073
%!   assert (x(1, 1, :)(:), uint8 ([0; 0; 0]));       # NaN
%!   assert (x(2, 1, :)(:), uint8 ([255; 255; 255])); # Inf
%!   ## Coloured pixels: luminance weights, not the channel maximum.
%!   img = repmat (reshape ([0 1 0], 1, 1, 3), 10, 10);
%!   stops = img_write_png (f, img, "AUTO");
%!   assert (stops, -log2 (0.7152), 1e-12);
%!   ## All black: exposure 0.
%!   assert (img_write_png (f, zeros (2, 2, 3), "auto"), 0);
%!   x = imread (f);                      # may be a 1-bit PNG (logical)
%!   assert (size (x), [2 2 3]);
%!   assert (all (x(:) == 0));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Failed writes: unwritable, the old file stays, no temporary file left.
%!test
%! d = tempname ();
%! mkdir (d);
%! unwind_protect
%!   f = fullfile (d, "keep.png");
%!   img_write_png (f, 0.5 * ones (2, 2, 3));
%!   old = imread (f);
%!   check_id ("lafortune:badImage", @img_write_png, f, ones (2, 2));
%!   check_id ("lafortune:badExposure", @img_write_png, f, ones (2, 2, 3), "x");
%!   assert (imread (f), old);
%!   mkdir (fullfile (d, "sub.png"));
%!   check_id ("lafortune:unwritable", @img_write_png, fullfile (d, "sub.png"),
%!             ones (2, 2, 3));
%!   check_id ("lafortune:unwritable", @img_write_png,
%!             fullfile (d, "missing", "x.png"), ones (2, 2, 3));
%!   lst = dir (d);
%!   assert ({lst.name}, {".", "..", "keep.png", "sub.png"});
%!   assert (imread (f), old);
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

## Input validation.
%!error <Invalid call> img_write_png ()
%!error <Invalid call> img_write_png ("a.png")
%!error <called with too many inputs> img_write_png ("a.png", ones (2, 2, 3), 0, 1)
%!error id=lafortune:badFile img_write_png (1, ones (2, 2, 3))
%!error id=lafortune:badFile img_write_png ("", ones (2, 2, 3))
%!error <got 2x2 double> img_write_png ("a.png", ones (2, 2))
%!error <got 2x2x4 double> img_write_png ("a.png", ones (2, 2, 4))
%!error <complex> img_write_png ("a.png", complex (ones (2, 2, 3), 1))
%!error <got 2x2x3 uint8> img_write_png ("a.png", uint8 (ones (2, 2, 3)))
%!error id=lafortune:badImage img_write_png ("a.png", zeros (0, 2, 3))
%!error id=lafortune:badImage img_write_png ("a.png", {1})
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), "bright")
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), [1 2])
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), NaN)
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), Inf)
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), 1i)
%!error id=lafortune:badExposure img_write_png ("a.png", ones (2, 2, 3), true)
