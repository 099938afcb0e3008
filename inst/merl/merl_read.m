## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn  {lafortune} {@var{brdf} =} merl_read (@var{file})
## Read a MERL BRDF database file (@file{.binary}).
##
## The format: three int32 little-endian dimensions (90, 90, 180: theta_h,
## theta_d, phi_d), then 3 x 1,458,000 float64, channel-major (R, G, B), each
## stored divided by its scale (1/1500, 1.15/1500, 1.66/1500).  Returns a
## struct with fields
##
## @table @code
## @item name
## the file's base name without extension
## @item file
## the file name as given
## @item data
## 1458000 x 3 double, the scaled values in the database's bin order
## (phi_d fastest, then theta_d, then theta_h)
## @item valid
## 1458000 x 1 logical, false where any channel is negative (the database
## stores -1 for missing samples); fitting never uses invalid samples
## @end table
##
## Errors (ids): @code{lafortune:fileNotFound}, @code{lafortune:isDirectory},
## @code{lafortune:bigEndian} (a byte-swapped header),
## @code{lafortune:badHeader}, @code{lafortune:truncated},
## @code{lafortune:badPayload} (NaN or Inf values).
##
## @example
## @group
## brdf = merl_read ("red-plastic.binary");   # a file of the MERL database
## printf ("%d of %d samples valid\n", nnz (brdf.valid), numel (brdf.valid));
## @end group
## @end example
## @seealso{merl_write, merl_eval, merl_plane, merl_synth}
## @end deftypefn
function brdf = merl_read (file)
  if (nargin != 1)
    print_usage ();
  endif
  if (! ischar (file) || rows (file) != 1)
    error ("lafortune:badFile", "merl_read: FILE must be a file name (string)");
  endif
  if (isfolder (file))
    error ("lafortune:isDirectory", "merl_read: '%s' is a directory, expected a MERL .binary file", file);
  endif
  [fid, msg] = fopen (file, "r", "ieee-le");
  if (fid < 0)
    error ("lafortune:fileNotFound", "merl_read: cannot open '%s': %s", file, msg);
  endif
  c = onCleanup (@() fclose (fid));
  [dims, scale, n] = __lafortune_merl_consts__ ();
  [hdr, cnt] = fread (fid, 3, "int32=>double");
  if (cnt < 3)
    error ("lafortune:truncated",
           "merl_read: '%s' is truncated: %d bytes, a MERL header needs 12", file, 4 * cnt);
  endif
  hdr = hdr';
  if (! isequal (hdr, dims))
    swapped = double (swapbytes (int32 (hdr)));
    if (isequal (swapped, dims))
      error ("lafortune:bigEndian",
             "merl_read: '%s' has a big-endian header (byte-swapped dims 90 90 180); MERL files are little-endian",
             file);
    endif
    error ("lafortune:badHeader",
           "merl_read: '%s' has header dims %s, expected [90 90 180] (not a MERL .binary file?)",
           file, mat2str (hdr));
  endif
  [raw, cnt] = fread (fid, 3 * n, "float64=>double");
  if (cnt < 3 * n)
    error ("lafortune:truncated",
           "merl_read: '%s' is truncated: %d of %d values (file of %d bytes, expected %d)",
           file, cnt, 3 * n, 12 + 8 * cnt, 12 + 24 * n);
  endif
  fread (fid, 1, "uint8");
  if (! feof (fid))
    error ("lafortune:badHeader",
           "merl_read: '%s' is longer than a MERL file (%d bytes expected)", file, 12 + 24 * n);
  endif
  if (! all (isfinite (raw)))
    k = find (! isfinite (raw), 1);
    error ("lafortune:badPayload",
           "merl_read: '%s' holds NaN or Inf (first at value %d); MERL values are finite",
           file, k);
  endif
  data = reshape (raw, n, 3) .* scale;
  [~, name] = fileparts (file);
  brdf = struct ("name", name, "file", file, "data", data, "valid", all (data >= 0, 2));
endfunction

%!demo
%! ## make a MERL-format material and read it back, as with a database file
%! m = struct ("rho_d", [0.2 0.05 0.02], "Cxy", [-1 -1 -1], "Cz", [1 1 1], "e", [40 40 40]);
%! f = [tempname() ".binary"];
%! merl_write (f, merl_synth (m, "missing", 80));
%! brdf = merl_read (f);
%! printf ("%s: %d of %d bins valid\n", brdf.name, nnz (brdf.valid), numel (brdf.valid));
%! delete (f);

%!shared f, d
%! d = tempname (); mkdir (d);
%! f = fullfile (d, "m.binary");
%! b = merl_synth (@(wi, wo) [wi(:,3) + wo(:,3), wo(:,3) .* wi(:,3), ones(rows (wi), 1)], "missing", 75);
%! merl_write (f, b);

%!test
%! b = merl_read (f);
%! assert (b.name, "m");
%! assert (b.file, f);
%! assert (size (b.data), [1458000 3]);
%! assert (any (! b.valid) && any (b.valid));
%! assert (all (b.data(! b.valid, :)(:) < 0));

%!test
%! ## read-write-read is bit-exact
%! b1 = merl_read (f);
%! f2 = fullfile (d, "m2.binary");
%! merl_write (f2, b1);
%! b2 = merl_read (f2);
%! assert (isequal (b1.data, b2.data) && isequal (b1.valid, b2.valid));
%! delete (f2);

%!test
%! ## the stand-in files in shared/, when present
%! ## MERL_PROXY_DIR is set by `make check`; by default ../shared/data/merl-proxy
%! pd = getenv ("MERL_PROXY_DIR");
%! if (isempty (pd))
%!   pd = fullfile (pwd, "..", "shared", "data", "merl-proxy");
%! endif
%! p = fullfile (pd, "red-plastic.binary");
%! if (exist (p, "file"))
%!   b = merl_read (p);
%!   assert (b.name, "red-plastic");
%!   assert (nnz (b.valid) > 1e6);
%! else
%!   printf ("skipped: %s absent\n", p);
%! endif

%!function bad_file (f, bytes, precision = "uint8", arch = "ieee-le")
%!  fid = fopen (f, "w", arch); fwrite (fid, bytes, precision); fclose (fid);
%!endfunction

%!error <Invalid call> merl_read ()
%!error id=lafortune:fileNotFound merl_read (fullfile (d, "nope.binary"))
%!error id=lafortune:isDirectory merl_read (d)
%!error <truncated> bad_file (fullfile (d, "t1"), [90 90], "int32"), merl_read (fullfile (d, "t1"))
%!error <is truncated: 10 of> bad_file (fullfile (d, "t2"), [90 90 180 zeros(1, 20)], "int32"), merl_read (fullfile (d, "t2"))
%!error id=lafortune:badHeader bad_file (fullfile (d, "h"), [90 90 90 zeros(1, 20)], "int32"), merl_read (fullfile (d, "h"))
%!error id=lafortune:bigEndian bad_file (fullfile (d, "be"), [90 90 180 zeros(1, 20)], "int32", "ieee-be"), merl_read (fullfile (d, "be"))
%!error <holds NaN or Inf> fid = fopen (fullfile (d, "nan"), "w"); fwrite (fid, [90 90 180], "int32"); fwrite (fid, [1 NaN zeros(1, 3*1458000-2)], "float64"); fclose (fid); merl_read (fullfile (d, "nan"))
%!error id=lafortune:badFile merl_read (42)
%!test
%! ## remove only the scratch folder this file made
%! assert (strncmp (d, tempdir (), numel (tempdir ())));
%! confirm_recursive_rmdir (false, "local");
%! rmdir (d, "s");
