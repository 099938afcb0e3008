## Copyright (C) 2026 The lafortune developers
## SPDX-License-Identifier: GPL-3.0-or-later

## -*- texinfo -*-
## @deftypefn {} {} atomic_write (@var{file}, @var{fname}, @var{writer})
## @deftypefnx {} {} atomic_write (@var{file}, @var{fname}, @var{writer}, @var{arch})
## Write @var{file} through a temporary file in its folder and a rename
## (private).  @var{writer} is called as @code{ok = writer (fid)} and returns
## true when everything was written; @var{arch} is fopen's byte order
## (default "native").  On any failure the temporary file is removed, an
## earlier @var{file} is left as it was, and the error is
## @code{lafortune:unwritable} (or the writer's own).
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
      good = writer (fid);
    catch err
      fclose (fid);
      rethrow (err);
    end_try_catch
    if (fclose (fid) != 0 || ! good)
      error ("lafortune:unwritable", "%s: writing '%s' failed (disk full?)", fname, file);
    endif
    atomic_commit (tmp, file, fname);
    ok = true;
  unwind_protect_cleanup
    if (! ok && exist (tmp, "file"))
      unlink (tmp);
    endif
  end_unwind_protect
endfunction
