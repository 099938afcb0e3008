## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} atomic_write (@var{file}, @var{fname}, @var{writer})
## @deftypefnx {} {} atomic_write (@var{file}, @var{fname}, @var{writer}, @var{arch})
## Write @var{file} through a temporary file in its folder and a rename
## (private).  @var{writer} is called as @code{nbytes = writer (fid)} and
## returns the number of bytes it wrote (negative when it saw a failure);
## @var{arch} is fopen's byte order (default "native").  The temporary file
## must have exactly that size before it is renamed: Octave's fwrite, fputs
## and fclose do not report a disk that refuses the data (full, or over a
## size limit).  On any failure the temporary file is removed, an earlier
## @var{file} is left as it was, and the error is @code{lafortune:unwritable}
## (or the writer's own).
## @end deftypefn
function atomic_write (file, fname, writer, arch = "native")
  tmp = atomic_tmp (file, fname);
  ok = false;
  unwind_protect
    fid = fopen (tmp, "w", arch);
    if (fid < 0)
      error ("lafortune:unwritable", "%s: cannot write '%s'", fname, tmp);
    endif
    try
      nbytes = writer (fid);
    catch err
      fclose (fid);
      rethrow (err);
    end_try_catch
    st = fclose (fid);
    [info, err] = stat (tmp);
    if (st != 0 || nbytes < 0 || err != 0 || info.size != nbytes)
      error ("lafortune:unwritable", "%s: writing '%s' failed (disk full or a file size limit?)",
             fname, file);
    endif
    atomic_commit (tmp, file, fname);
    ok = true;
  unwind_protect_cleanup
    if (! ok && exist (tmp, "file"))
      unlink (tmp);
    endif
  end_unwind_protect
endfunction
