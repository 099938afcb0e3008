// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// exrwrite: write an RGB or RGBA image to an OpenEXR file (float32 or half
// channels, ZIP compression) through the OpenEXR C++ API.  The file is
// written to a temporary file in the target folder and renamed onto the
// target, so a failed write leaves any existing file untouched.

#include <octave/oct.h>

#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <Iex.h>
#include <half.h>

namespace
{
  // Interleaved, row-major sample buffer (what OpenEXR reads fastest).
  // img is column-major H x W x NC; sample (y, x, c) goes to
  // buf[(y*W + x)*NC + c].
  template <typename OUT, typename IN>
  void
  interleave (std::vector<OUT>& buf, const IN *src, octave_idx_type h,
              octave_idx_type w, octave_idx_type nc)
  {
    buf.resize (h * w * nc);
    for (octave_idx_type c = 0; c < nc; c++)
      for (octave_idx_type x = 0; x < w; x++)
        {
          const IN *col = src + c*h*w + x*h;
          OUT *dst = buf.data () + x*nc + c;
          for (octave_idx_type y = 0; y < h; y++)
            dst[y*w*nc] = OUT (static_cast<float> (col[y]));
        }
  }

  std::string
  dirname_of (const std::string& file)
  {
    std::size_t pos = file.find_last_of ('/');
    if (pos == std::string::npos)
      return ".";
    if (pos == 0)
      return "/";
    return file.substr (0, pos);
  }

  // Mode for the new file: keep the mode of an existing target, else
  // 0666 minus the umask (what a plain open () would give).
  mode_t
  target_mode (const std::string& file)
  {
    struct stat st;
    if (stat (file.c_str (), &st) == 0 && S_ISREG (st.st_mode))
      return st.st_mode & 07777;
    mode_t mask = umask (0);
    umask (mask);
    return 0666 & ~mask;
  }
}

DEFUN_DLD (exrwrite, args, ,
           R"doc(-*- texinfo -*-
@deftypefn  {} {} exrwrite (@var{file}, @var{img})
@deftypefnx {} {} exrwrite (@var{file}, @var{img}, @var{type})
Write the linear HDR image @var{img} to the OpenEXR file @var{file}.

@var{img} is an @var{H} x @var{W} x 3 (RGB) or @var{H} x @var{W} x 4 (RGBA)
real @code{double} or @code{single} array.  Row 1 of @var{img} is the top
scanline of the image (y = 0 in the EXR data window), column 1 the left
column.  Inf and NaN values are stored as they are.

@var{type} selects the channel type: @qcode{"float"} (32-bit float, the
default; a @code{single} image round-trips bit-exactly) or @qcode{"half"}
(16-bit float, about 3 significant digits, largest finite value 65504).
The file uses ZIP compression.

The image is written to a temporary file in the folder of @var{file} that is
then renamed onto @var{file}, so a failed write never leaves a partial file
and never destroys an existing @var{file}.

Errors have the identifiers @code{lafortune:exrBadInput} (wrong arguments)
and @code{lafortune:exrWrite} (the file could not be written).

Example:

@example
@group
img = rand (4, 6, 3);
exrwrite ("out.exr", img);            # float32 channels
exrwrite ("out_half.exr", img, "half");
back = exrread ("out.exr");
isequal (back, double (single (img)))
  @result{} 1
@end group
@end example

@seealso{exrread, img_write_png}
@end deftypefn)doc")
{
  int nargin = args.length ();
  if (nargin < 2 || nargin > 3)
    print_usage ();

  if (! args(0).is_string () || args(0).rows () > 1 || args(0).isempty ())
    error_with_id ("lafortune:exrBadInput",
                   "exrwrite: FILE must be a non-empty character string");
  std::string file = args(0).string_value ();

  bool use_half = false;
  if (nargin == 3)
    {
      if (! args(2).is_string () || args(2).rows () > 1)
        error_with_id ("lafortune:exrBadInput",
                       "exrwrite: TYPE must be \"float\" or \"half\"");
      std::string t = args(2).string_value ();
      for (auto& ch : t)
        ch = std::tolower (static_cast<unsigned char> (ch));
      if (t == "half")
        use_half = true;
      else if (t != "float")
        error_with_id ("lafortune:exrBadInput",
                       "exrwrite: TYPE must be \"float\" or \"half\", got \"%s\"",
                       args(2).string_value ().c_str ());
    }

  octave_value img = args(1);
  if (! (img.is_double_type () || img.is_single_type ()) || img.iscomplex ())
    error_with_id ("lafortune:exrBadInput",
                   "exrwrite: IMG must be a real double or single array, got %s%s",
                   img.iscomplex () ? "complex " : "",
                   img.class_name ().c_str ());

  dim_vector dv = img.dims ();
  if (dv.ndims () != 3 || (dv(2) != 3 && dv(2) != 4) || dv(0) < 1 || dv(1) < 1)
    error_with_id ("lafortune:exrBadInput",
                   "exrwrite: IMG must be H x W x 3 or H x W x 4 with H, W >= 1, got %d-D %s",
                   static_cast<int> (dv.ndims ()), dv.str ('x').c_str ());

  const octave_idx_type h = dv(0);
  const octave_idx_type w = dv(1);
  const octave_idx_type nc = dv(2);
  if (h > 0x7fffffffL || w > 0x7fffffffL)
    error_with_id ("lafortune:exrBadInput",
                   "exrwrite: IMG is too large for OpenEXR (%s)",
                   dv.str ('x').c_str ());

  // Convert to an interleaved buffer of the output sample type.
  std::vector<float> fbuf;
  std::vector<half> hbuf;
  if (img.is_single_type ())
    {
      const FloatNDArray a = img.float_array_value ();
      if (use_half)
        interleave (hbuf, a.data (), h, w, nc);
      else
        interleave (fbuf, a.data (), h, w, nc);
    }
  else
    {
      const NDArray a = img.array_value ();
      if (use_half)
        interleave (hbuf, a.data (), h, w, nc);
      else
        interleave (fbuf, a.data (), h, w, nc);
    }

  // Create the temporary file next to the target.
  std::string tmpl = file + ".tmpXXXXXX";
  std::vector<char> tmpname (tmpl.begin (), tmpl.end ());
  tmpname.push_back ('\0');
  mode_t mode = target_mode (file);
  int fd = mkstemp (tmpname.data ());
  if (fd < 0)
    {
      int err = errno;
      error_with_id ("lafortune:exrWrite",
                     "exrwrite: cannot create a file in '%s' to write '%s': %s",
                     dirname_of (file).c_str (), file.c_str (),
                     std::strerror (err));
    }
  std::string tmp (tmpname.data ());
  fchmod (fd, mode);
  close (fd);

  // Write it.  Octave's error () throws, so it is only called after the
  // try block, once the temporary file has been removed.
  std::string errmsg;
  try
    {
      std::ofstream ofs (tmp.c_str (), std::ios_base::binary
                                       | std::ios_base::out
                                       | std::ios_base::trunc);
      if (! ofs)
        throw std::runtime_error ("cannot open the temporary file");
      {
        Imf::StdOFStream os (ofs, tmp.c_str ());

        Imf::Header header (static_cast<int> (w), static_cast<int> (h));
        header.compression () = Imf::ZIP_COMPRESSION;
        Imf::PixelType pt = use_half ? Imf::HALF : Imf::FLOAT;
        static const char *names[4] = {"R", "G", "B", "A"};
        for (octave_idx_type c = 0; c < nc; c++)
          header.channels ().insert (names[c], Imf::Channel (pt));

        std::size_t ss = use_half ? sizeof (half) : sizeof (float);
        char *base = use_half ? reinterpret_cast<char *> (hbuf.data ())
                              : reinterpret_cast<char *> (fbuf.data ());
        Imf::FrameBuffer fb;
        for (octave_idx_type c = 0; c < nc; c++)
          fb.insert (names[c],
                     Imf::Slice (pt, base + c*ss, nc*ss, w*nc*ss));

        Imf::OutputFile out (os, header);
        out.setFrameBuffer (fb);
        out.writePixels (static_cast<int> (h));
        // The destructor writes the offset table; its errors are swallowed
        // by OpenEXR but leave the stream in a failed state, checked below.
      }
      ofs.flush ();
      if (! ofs)
        throw std::runtime_error ("error while finishing the file");
      ofs.close ();
      if (! ofs)
        throw std::runtime_error ("error while closing the file");

      if (std::rename (tmp.c_str (), file.c_str ()) != 0)
        {
          int err = errno;
          throw std::runtime_error (std::string ("cannot rename the temporary file onto the target: ")
                                    + std::strerror (err));
        }
    }
  catch (const Iex::BaseExc& e)
    {
      errmsg = e.what ();
    }
  catch (const std::bad_alloc&)
    {
      errmsg = "out of memory";
    }
  catch (const std::exception& e)
    {
      errmsg = e.what ();
    }
  catch (...)
    {
      errmsg = "unknown error";
    }

  if (! errmsg.empty ())
    {
      std::remove (tmp.c_str ());
      error_with_id ("lafortune:exrWrite", "exrwrite: cannot write '%s': %s",
                     file.c_str (), errmsg.c_str ());
    }

  return octave_value_list ();
}

/*
## Round trip of float32 data is bit-exact (single input).
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   rand ("seed", 1);
%!   img = single (rand (7, 5, 3) * 100 - 20);
%!   exrwrite (f, img);
%!   back = exrread (f);
%!   assert (class (back), "double");
%!   assert (size (back), [7 5 3]);
%!   assert (isequal (back, double (img)));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Double input is stored as float32: equals the single-rounded values.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   img = randn (5, 9, 4) * 1e3;
%!   exrwrite (f, img, "float");
%!   [back, info] = exrread (f);
%!   assert (size (back), [5 9 4]);
%!   assert (isequal (back, double (single (img))));
%!   assert (info.channels, {"A", "B", "G", "R"});
%!   assert (info.pixel_types, {"float", "float", "float", "float"});
%!   assert (info.compression, "zip");
%!   assert ([info.width info.height], [9 5]);
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Single row, single column, single pixel; orientation (row 1 = top).
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   for sz = {[1 11], [13 1], [1 1]}
%!     img = reshape (single (1:prod (sz{1})*3), [sz{1} 3]);
%!     exrwrite (f, img);
%!     back = exrread (f);
%!     assert (size (back), [sz{1} 3]);
%!     assert (isequal (back, double (img)));
%!   endfor
%!   img = zeros (3, 2, 3);
%!   img(1, 2, 1) = 5;       # top right, red
%!   exrwrite (f, img);
%!   [back, info] = exrread (f);
%!   assert (back(1, 2, 1), 5);
%!   assert (nnz (back), 1);
%!   assert (info.data_window, [0 0 1 2]);
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Half round trip: rel. error < 1e-3 (half has 11 significant bits).
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   rand ("seed", 2);
%!   img = 10 .^ (rand (6, 7, 3) * (log10 (6e4) + 3) - 3);
%!   img(1, 1, :) = [1e-3 6e4 1];
%!   exrwrite (f, img, "half");
%!   [back, info] = exrread (f);
%!   assert (info.pixel_types, {"half", "half", "half"});
%!   assert (size (back), size (img));
%!   assert (max (abs (back(:) ./ img(:) - 1)) < 1e-3);
%!   assert (! isequal (back, double (single (img))));  # really half
%!   exrwrite (f, img, "HALF");
%!   assert (isequal (exrread (f), back));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Inf and NaN pass through, float and half; half overflows to Inf.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   img = ones (2, 3, 3);
%!   img(1, 1, 1) = Inf;  img(2, 3, 2) = -Inf;  img(1, 2, 3) = NaN;
%!   for t = {"float", "half"}
%!     exrwrite (f, img, t{1});
%!     back = exrread (f);
%!     assert (back, img);
%!   endfor
%!   exrwrite (f, 1e6 * ones (1, 1, 3), "half");
%!   assert (exrread (f), Inf (1, 1, 3));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## A failed write keeps the old file and leaves no temporary file behind.
%!function check_id (id, fcn, varargin)
%!  try
%!    fcn (varargin{:});
%!  catch err
%!    assert (err.identifier, id);
%!    return;
%!  end_try_catch
%!  error ("expected an error with identifier %s", id);
%!endfunction

%!test
%! d = tempname ();
%! mkdir (d);
%! f = fullfile (d, "keep.exr");
%! unwind_protect
%!   img = rand (4, 4, 3);
%!   exrwrite (f, img);
%!   fid = fopen (f, "r");  old = fread (fid, Inf, "uint8=>uint8");  fclose (fid);
%!   check_id ("lafortune:exrBadInput", @exrwrite, f, rand (4, 4));
%!   check_id ("lafortune:exrBadInput", @exrwrite, f, img, "int");
%!   fid = fopen (f, "r");  now = fread (fid, Inf, "uint8=>uint8");  fclose (fid);
%!   assert (isequal (now, old));
%!   lst = dir (d);
%!   assert ({lst.name}, {".", "..", "keep.exr"});
%!   ## Target is a directory: the rename fails, the temp file is removed.
%!   mkdir (fullfile (d, "sub.exr"));
%!   check_id ("lafortune:exrWrite", @exrwrite, fullfile (d, "sub.exr"), img);
%!   lst = dir (d);
%!   assert ({lst.name}, {".", "..", "keep.exr", "sub.exr"});
%!   ## Overwriting works and replaces the content.
%!   exrwrite (f, 2 * ones (4, 4, 3));
%!   assert (exrread (f), 2 * ones (4, 4, 3));
%!   lst = dir (d);
%!   assert ({lst.name}, {".", "..", "keep.exr", "sub.exr"});
%! unwind_protect_cleanup
%!   confirm_recursive_rmdir (false, "local");
%!   rmdir (d, "s");
%! end_unwind_protect

## Unwritable paths (missing folder; a "folder" that is a regular file):
## lafortune:exrWrite with the path in the message.
%!test
%! d = tempname ();
%! fplain = [tempname() ".txt"];
%! unwind_protect
%!   fid = fopen (fplain, "w");  fputs (fid, "x");  fclose (fid);
%!   for f = {fullfile(d, "x.exr"), fullfile(fplain, "x.exr")}
%!     try
%!       exrwrite (f{1}, rand (2, 2, 3));
%!       error ("expected an error");
%!     catch err
%!       assert (err.identifier, "lafortune:exrWrite");
%!       assert (! isempty (strfind (err.message, f{1})));
%!     end_try_catch
%!   endfor
%!   assert (! exist (d, "file"));
%! unwind_protect_cleanup
%!   unlink (fplain);
%! end_unwind_protect

## Input validation.
%!error <Invalid call> exrwrite ()
%!error <Invalid call> exrwrite ("x.exr")
%!error <Invalid call> exrwrite ("x.exr", 1, "half", 4)
%!error id=lafortune:exrBadInput exrwrite (3, rand (2, 2, 3))
%!error id=lafortune:exrBadInput exrwrite ("", rand (2, 2, 3))
%!error <got 2-D 5x4> exrwrite ("x.exr", rand (5, 4))
%!error <H x W x 3 or H x W x 4> exrwrite ("x.exr", rand (5, 4, 2))
%!error id=lafortune:exrBadInput exrwrite ("x.exr", rand (5, 4, 3, 2))
%!error id=lafortune:exrBadInput exrwrite ("x.exr", zeros (0, 4, 3))
%!error <real double or single> exrwrite ("x.exr", uint8 (rand (2, 2, 3)))
%!error <complex> exrwrite ("x.exr", complex (rand (2, 2, 3), 1))
%!error id=lafortune:exrBadInput exrwrite ("x.exr", true (2, 2, 3))
%!error <"float" or "half"> exrwrite ("x.exr", rand (2, 2, 3), "double")
%!error id=lafortune:exrBadInput exrwrite ("x.exr", rand (2, 2, 3), 16)
*/
