// Copyright (C) 2026 The lafortune developers
// SPDX-License-Identifier: GPL-3.0-or-later
//
// exrread: read the R, G, B (and A) channels of an OpenEXR file (scanline or
// tiled; half, float or uint channels) into an H x W x 3 (or 4) double
// array through the OpenEXR C++ API.

#include <octave/oct.h>
#include <octave/ov-struct.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <sys/types.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfVersion.h>
#include <Iex.h>

namespace
{
  const char *
  compression_name (Imf::Compression c)
  {
    switch (c)
      {
      case Imf::NO_COMPRESSION: return "none";
      case Imf::RLE_COMPRESSION: return "rle";
      case Imf::ZIPS_COMPRESSION: return "zips";
      case Imf::ZIP_COMPRESSION: return "zip";
      case Imf::PIZ_COMPRESSION: return "piz";
      case Imf::PXR24_COMPRESSION: return "pxr24";
      case Imf::B44_COMPRESSION: return "b44";
      case Imf::B44A_COMPRESSION: return "b44a";
      case Imf::DWAA_COMPRESSION: return "dwaa";
      case Imf::DWAB_COMPRESSION: return "dwab";
      default: return "unknown";
      }
  }

  const char *
  type_name (Imf::PixelType t)
  {
    switch (t)
      {
      case Imf::UINT: return "uint";
      case Imf::HALF: return "half";
      case Imf::FLOAT: return "float";
      default: return "unknown";
      }
  }

  // Everything read from the file, filled inside the try block so that
  // Octave's error () (which throws) is only called outside of it.
  struct exr_result
  {
    std::string err_id;
    std::string err_msg;
    octave_idx_type h = 0, w = 0, nc = 0;
    NDArray img;
    std::vector<std::string> names;
    std::vector<std::string> types;
    std::string compression;
    int dw[4] = {0, 0, 0, 0};
    int dispw[4] = {0, 0, 0, 0};
    bool tiled = false;
  };

  void
  read_exr (const std::string& file, exr_result& r)
  {
    Imf::InputFile in (file.c_str ());
    const Imf::Header& hdr = in.header ();

    const Imf::ChannelList& chl = hdr.channels ();
    std::map<std::string, Imf::Channel> present;
    for (auto it = chl.begin (); it != chl.end (); ++it)
      {
        r.names.push_back (it.name ());
        r.types.push_back (type_name (it.channel ().type));
        present[it.name ()] = it.channel ();
      }
    r.compression = compression_name (hdr.compression ());
    r.tiled = hdr.hasTileDescription ();

    const Imath::Box2i& dw = hdr.dataWindow ();
    const Imath::Box2i& dispw = hdr.displayWindow ();
    r.dw[0] = dw.min.x; r.dw[1] = dw.min.y; r.dw[2] = dw.max.x; r.dw[3] = dw.max.y;
    r.dispw[0] = dispw.min.x; r.dispw[1] = dispw.min.y;
    r.dispw[2] = dispw.max.x; r.dispw[3] = dispw.max.y;

    static const char *rgba[4] = {"R", "G", "B", "A"};
    if (! present.count ("R") || ! present.count ("G") || ! present.count ("B"))
      {
        std::string lst;
        for (const auto& n : r.names)
          lst += (lst.empty () ? "" : ", ") + n;
        if (lst.empty ())
          lst = "(none)";
        r.err_id = "lafortune:exrRead";
        r.err_msg = "has channels " + lst
                    + "; expected R, G, B (and optionally A)";
        return;
      }
    r.nc = present.count ("A") ? 4 : 3;
    for (int c = 0; c < r.nc; c++)
      {
        const Imf::Channel& ch = present[rgba[c]];
        if (ch.xSampling != 1 || ch.ySampling != 1)
          {
            r.err_id = "lafortune:exrRead";
            r.err_msg = std::string ("channel ") + rgba[c]
                        + " is subsampled, which is not supported";
            return;
          }
      }

    const int64_t w = int64_t (dw.max.x) - dw.min.x + 1;
    const int64_t h = int64_t (dw.max.y) - dw.min.y + 1;
    if (w < 1 || h < 1)
      {
        r.err_id = "lafortune:exrRead";
        r.err_msg = "has an empty data window";
        return;
      }
    r.w = w;
    r.h = h;

    // One 4-byte sample buffer per channel, column-major (the Octave
    // layout): sample (x, y) at [x*h + y].  Half and float channels are
    // read as float, uint channels as uint.
    const std::size_t n = std::size_t (w) * std::size_t (h);
    std::vector<std::vector<float>> fbuf (r.nc);
    std::vector<std::vector<uint32_t>> ubuf (r.nc);
    std::vector<bool> is_uint (r.nc);
    Imf::FrameBuffer fb;
    for (int c = 0; c < r.nc; c++)
      {
        is_uint[c] = (present[rgba[c]].type == Imf::UINT);
        const void *base;
        if (is_uint[c])
          {
            ubuf[c].assign (n, 0);
            base = ubuf[c].data ();
          }
        else
          {
            fbuf[c].assign (n, 0.0f);
            base = fbuf[c].data ();
          }
        fb.insert (rgba[c],
                   Imf::Slice::Make (is_uint[c] ? Imf::UINT : Imf::FLOAT,
                                     base, dw, std::size_t (h) * 4, 4));
      }
    in.setFrameBuffer (fb);
    in.readPixels (dw.min.y, dw.max.y);

    r.img = NDArray (dim_vector (h, w, r.nc));
    double *out = r.img.fortran_vec ();
    for (int c = 0; c < r.nc; c++)
      {
        double *dst = out + c * n;
        if (is_uint[c])
          {
            const uint32_t *src = ubuf[c].data ();
            for (std::size_t i = 0; i < n; i++)
              dst[i] = src[i];
          }
        else
          {
            const float *src = fbuf[c].data ();
            for (std::size_t i = 0; i < n; i++)
              dst[i] = src[i];
          }
        // Release the sample buffer early.
        std::vector<float> ().swap (fbuf[c]);
        std::vector<uint32_t> ().swap (ubuf[c]);
      }
  }

  Cell
  to_cellstr (const std::vector<std::string>& v)
  {
    Cell c (1, v.size ());
    for (std::size_t i = 0; i < v.size (); i++)
      c(i) = v[i];
    return c;
  }

  RowVector
  to_row (const int *v)
  {
    RowVector rv (4);
    for (int i = 0; i < 4; i++)
      rv(i) = v[i];
    return rv;
  }
}

DEFUN_DLD (exrread, args, nargout,
           R"doc(-*- texinfo -*-
@deftypefn  {} {@var{img} =} exrread (@var{file})
@deftypefnx {} {[@var{img}, @var{info}] =} exrread (@var{file})
Read the RGB or RGBA OpenEXR image @var{file}.

@var{img} is an @var{H} x @var{W} x 3 @code{double} array (x 4 when the file
has an A channel), where @var{H} x @var{W} is the size of the data window.
Row 1 is the top scanline (smallest y), column 1 the leftmost column.
Scanline and tiled files (level 0 of tiled files) with half, float or uint
channels are read; inf and NaN values are returned as they are.  The file
must have R, G and B channels; other channels are ignored.

The optional struct @var{info} has the fields

@table @code
@item width
@itemx height
Size of the data window in pixels.
@item channels
Cellstr with the names of all channels in the file (EXR order).
@item pixel_types
Cellstr with the type of each channel: @qcode{"half"}, @qcode{"float"} or
@qcode{"uint"}.
@item compression
Compression name, e.g., @qcode{"none"}, @qcode{"zip"}, @qcode{"piz"}.
@item data_window
@itemx display_window
@code{[xmin, ymin, xmax, ymax]} in EXR pixel coordinates.
@item tiled
True for a tiled file.
@end table

Errors have the identifiers @code{lafortune:exrNotFound} (no such file, or
a folder), @code{lafortune:exrNotExr} (not an OpenEXR file: wrong magic
number) and @code{lafortune:exrRead} (unreadable, truncated or corrupt file,
missing R, G or B channel).

Example:

@example
@group
exrwrite ("out.exr", rand (4, 6, 3));
[img, info] = exrread ("out.exr");
size (img)
  @result{} 4   6   3
info.channels
  @result{} @{ [1,1] = B  [1,2] = G  [1,3] = R @}
@end group
@end example

@seealso{exrwrite, img_write_png}
@end deftypefn)doc")
{
  if (args.length () != 1)
    print_usage ();
  if (! args(0).is_string () || args(0).rows () > 1 || args(0).isempty ())
    error_with_id ("lafortune:exrBadInput",
                   "exrread: FILE must be a non-empty character string");
  std::string file = args(0).string_value ();

  struct stat st;
  if (stat (file.c_str (), &st) != 0)
    {
      int err = errno;
      if (err == ENOENT || err == ENOTDIR)
        error_with_id ("lafortune:exrNotFound",
                       "exrread: file '%s' not found", file.c_str ());
      error_with_id ("lafortune:exrRead", "exrread: cannot access '%s': %s",
                     file.c_str (), std::strerror (err));
    }
  if (S_ISDIR (st.st_mode))
    error_with_id ("lafortune:exrNotFound",
                   "exrread: '%s' is a folder, expected an OpenEXR file",
                   file.c_str ());

  // Check the magic number ourselves for a clear message.
  {
    std::FILE *fp = std::fopen (file.c_str (), "rb");
    if (! fp)
      {
        int err = errno;
        error_with_id ("lafortune:exrRead", "exrread: cannot open '%s': %s",
                       file.c_str (), std::strerror (err));
      }
    char magic[4] = {0, 0, 0, 0};
    std::size_t got = std::fread (magic, 1, 4, fp);
    std::fclose (fp);
    if (got != 4 || ! Imf::isImfMagic (magic))
      error_with_id ("lafortune:exrNotExr",
                     "exrread: '%s' is not an OpenEXR file (%s)",
                     file.c_str (),
                     got != 4 ? "shorter than the 4-byte magic number"
                              : "wrong magic number, expected 76 2f 31 01");
  }

  exr_result r;
  try
    {
      read_exr (file, r);
    }
  catch (const Iex::BaseExc& e)
    {
      r.err_id = "lafortune:exrRead";
      r.err_msg = std::string ("cannot read the file: ") + e.what ();
    }
  catch (const std::bad_alloc&)
    {
      r.err_id = "lafortune:exrRead";
      r.err_msg = "out of memory (corrupt header or image too large)";
    }
  catch (const std::exception& e)
    {
      r.err_id = "lafortune:exrRead";
      r.err_msg = std::string ("cannot read the file: ") + e.what ();
    }
  catch (...)
    {
      r.err_id = "lafortune:exrRead";
      r.err_msg = "cannot read the file: unknown error";
    }
  if (! r.err_id.empty ())
    error_with_id (r.err_id.c_str (), "exrread: '%s': %s", file.c_str (),
                   r.err_msg.c_str ());

  octave_value_list retval (nargout > 1 ? 2 : 1);
  retval(0) = r.img;
  if (nargout > 1)
    {
      octave_scalar_map info;
      info.setfield ("width", double (r.w));
      info.setfield ("height", double (r.h));
      info.setfield ("channels", to_cellstr (r.names));
      info.setfield ("pixel_types", to_cellstr (r.types));
      info.setfield ("compression", r.compression);
      info.setfield ("data_window", to_row (r.dw));
      info.setfield ("display_window", to_row (r.dispw));
      info.setfield ("tiled", r.tiled);
      retval(1) = info;
    }
  return retval;
}

/*
## Shared helpers for the tests.
%!function check_id (id, fcn, varargin)
%!  try
%!    fcn (varargin{:});
%!  catch err
%!    assert (err.identifier, id);
%!    return;
%!  end_try_catch
%!  error ("expected an error with identifier %s", id);
%!endfunction

%!function write_bytes (f, b)
%!  fid = fopen (f, "w");
%!  fwrite (fid, b, "uint8");
%!  fclose (fid);
%!endfunction

%!function b = read_bytes (f)
%!  fid = fopen (f, "r");
%!  b = fread (fid, Inf, "uint8=>uint8");
%!  fclose (fid);
%!endfunction

## Minimal independent writer of uncompressed EXR files (scanline or
## ONE_LEVEL tiled), to test exrread on files exrwrite cannot make.
## NAMES: cellstr of channel names; TYPES: 0 uint, 1 half, 2 float per
## channel; PLANES: cell of H x W arrays (half: uint16 bit patterns);
## ORIGIN: [xmin ymin] of the data window; TILE: [] or [tile_w tile_h].
%!function write_raw_exr (f, names, types, planes, origin, tile)
%!  [names, p] = sort (names);
%!  types = types(p);
%!  planes = planes(p);
%!  [h, w] = size (planes{1});
%!  i32 = @(x) typecast (int32 (x), "uint8");
%!  attr = @(name, type, v) [uint8([double(name) 0 double(type) 0]) i32(numel (v)) v];
%!  chl = uint8 ([]);
%!  for c = 1:numel (names)
%!    chl = [chl uint8([double(names{c}) 0]) i32(types(c)) 0 0 0 0 i32([1 1])];
%!  endfor
%!  chl(end+1) = 0;
%!  box = i32 ([origin origin+[w h]-1]);
%!  hdr = [attr("channels", "chlist", chl) attr("compression", "compression", uint8(0)) ...
%!         attr("dataWindow", "box2i", box) attr("displayWindow", "box2i", box) ...
%!         attr("lineOrder", "lineOrder", uint8(0)) ...
%!         attr("pixelAspectRatio", "float", typecast (single (1), "uint8")) ...
%!         attr("screenWindowCenter", "v2f", typecast (single ([0 0]), "uint8")) ...
%!         attr("screenWindowWidth", "float", typecast (single (1), "uint8"))];
%!  version = uint8 ([2 0 0 0]);
%!  if (! isempty (tile))
%!    hdr = [hdr attr("tiles", "tiledesc", [typecast(uint32(tile), "uint8") uint8(0)])];
%!    version(2) = 2;
%!  endif
%!  hdr = [uint8([118 47 49 1]) version hdr uint8(0)];
%!  chunks = {};
%!  if (isempty (tile))
%!    for y = 1:h
%!      d = raw_samples (types, planes, y, 1:w);
%!      chunks{end+1} = [i32(origin(2)+y-1) i32(numel (d)) d];
%!    endfor
%!  else
%!    for ty = 0:ceil (h/tile(2))-1
%!      for tx = 0:ceil (w/tile(1))-1
%!        rows = ty*tile(2)+1:min (h, (ty+1)*tile(2));
%!        cols = tx*tile(1)+1:min (w, (tx+1)*tile(1));
%!        d = raw_samples (types, planes, rows, cols);
%!        chunks{end+1} = [i32([tx ty 0 0]) i32(numel (d)) d];
%!      endfor
%!    endfor
%!  endif
%!  pos = numel (hdr) + 8 * numel (chunks);
%!  offs = zeros (1, numel (chunks), "uint64");
%!  for k = 1:numel (chunks)
%!    offs(k) = pos;
%!    pos += numel (chunks{k});
%!  endfor
%!  fid = fopen (f, "w");
%!  fwrite (fid, [hdr typecast(offs, "uint8") chunks{:}], "uint8");
%!  fclose (fid);
%!endfunction

%!function b = raw_samples (types, planes, rows, cols)
%!  b = uint8 ([]);
%!  for y = rows
%!    for c = 1:numel (planes)
%!      v = planes{c}(y, cols);
%!      switch (types(c))
%!        case 0
%!          b = [b typecast(uint32(v), "uint8")];
%!        case 1
%!          b = [b typecast(uint16(v), "uint8")];
%!        case 2
%!          b = [b typecast(single(v), "uint8")];
%!      endswitch
%!    endfor
%!  endfor
%!endfunction

## Bit pattern of a half for positive normal values exactly representable.
%!function b = half_bits (x)
%!  e = floor (log2 (x));
%!  b = uint16 ((e + 15) * 1024 + round ((x ./ 2.^e - 1) * 1024));
%!endfunction

## Hand-made files: orientation, data window origin, half/float/uint
## channels, extra channels ignored, tiled files, channel-less files.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   R = [1 2 3 4 5; 6 7 8 9 10; 11 12 13 14 15];   # 3 x 5, row 1 = top
%!   G = R / 4;
%!   B = R * 2;
%!   A = R / 16;
%!   ## Half RGB (like POV-Ray +FE), data window origin at (-2, 7).
%!   write_raw_exr (f, {"R", "G", "B"}, [1 1 1],
%!                  {half_bits(R), half_bits(G), half_bits(B)}, [-2 7], []);
%!   [img, info] = exrread (f);
%!   assert (img, cat (3, R, G, B));
%!   assert (info.data_window, [-2 7 2 9]);
%!   assert (info.pixel_types, {"half", "half", "half"});
%!   assert (info.compression, "none");
%!   ## Float RGBA with an extra channel Z, which is ignored.
%!   write_raw_exr (f, {"R", "G", "B", "A", "Z"}, [2 2 2 2 2],
%!                  {R, G, B, A, -R}, [0 0], []);
%!   [img, info] = exrread (f);
%!   assert (img, cat (3, R, G, B, A));
%!   assert (info.channels, {"A", "B", "G", "R", "Z"});
%!   ## Mixed types, uint values beyond float precision stay exact.
%!   U = R + 2^31;
%!   write_raw_exr (f, {"R", "G", "B"}, [0 2 1], {U, G, half_bits(B)}, [5 5], []);
%!   [img, info] = exrread (f);
%!   assert (img, cat (3, U, G, B));
%!   assert (info.pixel_types, {"half", "float", "uint"});
%!   ## Tiled, tiles 2 x 2 (partial edge tiles), float and half.
%!   write_raw_exr (f, {"R", "G", "B"}, [2 2 2], {R, G, B}, [3 -4], [2 2]);
%!   [img, info] = exrread (f);
%!   assert (img, cat (3, R, G, B));
%!   assert (info.tiled, true);
%!   assert (info.data_window, [3 -4 7 -2]);
%!   write_raw_exr (f, {"R", "G", "B", "A"}, [1 1 1 1],
%!                  {half_bits(R), half_bits(G), half_bits(B), half_bits(A)},
%!                  [0 0], [4 1]);
%!   assert (exrread (f), cat (3, R, G, B, A));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Missing R, G or B: lafortune:exrRead naming the channels present.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   write_raw_exr (f, {"Y"}, 1, {half_bits(ones (2, 3))}, [0 0], []);
%!   check_id ("lafortune:exrRead", @exrread, f);
%!   try
%!     exrread (f);
%!   catch err
%!     assert (! isempty (strfind (err.message, "has channels Y;")));
%!     assert (! isempty (strfind (err.message, "expected R, G, B")));
%!   end_try_catch
%!   write_raw_exr (f, {"R", "G", "A"}, [2 2 2], {ones(2), ones(2), ones(2)},
%!                  [0 0], []);
%!   try
%!     exrread (f);
%!     error ("expected an error");
%!   catch err
%!     assert (err.identifier, "lafortune:exrRead");
%!     assert (! isempty (strfind (err.message, "has channels A, G, R;")));
%!   end_try_catch
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## RGB float32 round trip, odd sizes; info struct.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   rand ("seed", 3);
%!   img = single (rand (7, 5, 3));
%!   exrwrite (f, img);
%!   [back, info] = exrread (f);
%!   assert (isequal (back, double (img)));
%!   assert (info.width, 5);
%!   assert (info.height, 7);
%!   assert (info.channels, {"B", "G", "R"});
%!   assert (info.pixel_types, {"float", "float", "float"});
%!   assert (info.compression, "zip");
%!   assert (info.data_window, [0 0 4 6]);
%!   assert (info.display_window, [0 0 4 6]);
%!   assert (info.tiled, false);
%!   assert (isequal (exrread (f), back));
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## RGBA round trip, single row and single column.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   rand ("seed", 4);
%!   for sz = {[1 9], [9 1], [3 8]}
%!     img = single (randn ([sz{1} 4]) * 50);
%!     exrwrite (f, img);
%!     back = exrread (f);
%!     assert (size (back), [sz{1} 4]);
%!     assert (isequal (back, double (img)));
%!   endfor
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Missing file and folders: lafortune:exrNotFound.
%!test
%! check_id ("lafortune:exrNotFound", @exrread, [tempname() ".exr"]);
%! check_id ("lafortune:exrNotFound", @exrread, fullfile (tempname (), "x.exr"));
%! check_id ("lafortune:exrNotFound", @exrread, tempdir ());
%!error <not found> exrread ([tempname() ".exr"])
%!error <is a folder> exrread (tempdir ())

## Not an EXR: empty file, short file, text, random bytes.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   write_bytes (f, []);
%!   check_id ("lafortune:exrNotExr", @exrread, f);
%!   write_bytes (f, [118 47 49]);
%!   check_id ("lafortune:exrNotExr", @exrread, f);
%!   write_bytes (f, double ("P3\n2 2\n255\n"));
%!   check_id ("lafortune:exrNotExr", @exrread, f);
%!   rand ("seed", 5);
%!   b = floor (rand (1, 5000) * 256);
%!   b(1) = 0;
%!   write_bytes (f, b);
%!   check_id ("lafortune:exrNotExr", @exrread, f);
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Random bytes after a valid magic number (and after a valid version
## field): lafortune:exrRead, no crash.
%!test
%! f = [tempname() ".exr"];
%! unwind_protect
%!   for seed = 1:20
%!     rand ("seed", seed);
%!     b = floor (rand (1, 2000) * 256);
%!     b(1:4) = [118 47 49 1];
%!     if (seed > 10)
%!       b(5:8) = [2 0 0 0];
%!     endif
%!     write_bytes (f, b);
%!     check_id ("lafortune:exrRead", @exrread, f);
%!   endfor
%! unwind_protect_cleanup
%!   unlink (f);
%! end_unwind_protect

## Truncated files (float and half, RGB and RGBA): lafortune:exrRead.
%!test
%! f = [tempname() ".exr"];
%! g = [tempname() ".exr"];
%! unwind_protect
%!   rand ("seed", 6);
%!   for t = {"float", "half"}
%!     for nc = [3 4]
%!       exrwrite (f, rand (64, 48, nc), t{1});
%!       b = read_bytes (f);
%!       n = numel (b);
%!       for cut = unique ([4 5 8 10 50 100 300 1000 floor(n/2) n-100 n-1])
%!         write_bytes (g, b(1:cut));
%!         check_id ("lafortune:exrRead", @exrread, g);
%!       endfor
%!       assert (size (exrread (f)), [64 48 nc]);
%!     endfor
%!   endfor
%! unwind_protect_cleanup
%!   unlink (f);
%!   unlink (g);
%! end_unwind_protect

## Corrupt pixel data (bytes flipped after the header): an error or a
## result of the right size, never a crash.
%!test
%! f = [tempname() ".exr"];
%! g = [tempname() ".exr"];
%! unwind_protect
%!   exrwrite (f, rand (32, 32, 3));
%!   b = read_bytes (f);
%!   n = numel (b);
%!   for k = 1:10
%!     rand ("seed", 100 + k);
%!     c = b;
%!     idx = 400 + floor (rand (1, 20) * (n - 400));
%!     c(idx) = uint8 (floor (rand (1, 20) * 256));
%!     write_bytes (g, c);
%!     try
%!       img = exrread (g);
%!       assert (size (img), [32 32 3]);
%!     catch err
%!       assert (err.identifier, "lafortune:exrRead");
%!     end_try_catch
%!   endfor
%! unwind_protect_cleanup
%!   unlink (f);
%!   unlink (g);
%! end_unwind_protect

## Files made by an external writer (POV-Ray, half channels, +FE) when
## povray is installed: read, right size and values in a sane range.
%!test
%! [st, ~] = system ("command -v povray");
%! if (st != 0)
%!   printf ("skipped: povray not installed\n");
%! else
%!   d = tempname ();
%!   mkdir (d);
%!   unwind_protect
%!     pov = fullfile (d, "s.pov");
%!     fid = fopen (pov, "w");
%!     fputs (fid, "camera { location <0,0,-3> look_at <0,0,0> }\n");
%!     fputs (fid, "light_source { <2,4,-3> color rgb <1,1,1> }\n");
%!     fputs (fid, "sphere { <0,0,0>, 1 pigment { color rgb <1,0.5,0.25> } }\n");
%!     fclose (fid);
%!     out = fullfile (d, "s.exr");
%!     cmd = sprintf ("cd '%s' && povray +I'%s' +O'%s' +FE +W17 +H11 -D -V -GA +A0.0 2>&1",
%!                    d, pov, out);
%!     [st, txt] = system (cmd);
%!     assert (st == 0, "%s", txt);
%!     [img, info] = exrread (out);
%!     assert (size (img, 1), 11);
%!     assert (size (img, 2), 17);
%!     assert (any (size (img, 3) == [3 4]));
%!     assert (all (strcmp (info.pixel_types, "half")));
%!     assert (all (isfinite (img(:))));
%!     assert (max (img(:)) > 0.1);
%!     ## Centre pixel: on the sphere, red > green > blue.
%!     p = squeeze (img(6, 9, 1:3));
%!     assert (p(1) > p(2) && p(2) > p(3));
%!     ## Corner: background (black).
%!     assert (img(1, 1, 1:3)(:), zeros (3, 1));
%!   unwind_protect_cleanup
%!     confirm_recursive_rmdir (false, "local");
%!     rmdir (d, "s");
%!   end_unwind_protect
%! endif

## Input validation.
%!error <Invalid call> exrread ()
%!error <Invalid call> exrread ("a.exr", 2)
%!error id=lafortune:exrBadInput exrread (1)
%!error id=lafortune:exrBadInput exrread ("")
%!error id=lafortune:exrBadInput exrread (["ab"; "cd"])
*/
