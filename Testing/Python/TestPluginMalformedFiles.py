# SPDX-License-Identifier: BSD-3-Clause
"""ParaView survives malformed files: every kind of file the plugin reads,
damaged, is opened through the plugin's readers as a user would (File > Open
picks the reader; the NIfTI files also through both NIfTI readers by name),
shown and rendered; each read must fail with the reader's error and an empty
output, and then a good tractogram must still render in the same session.

The damaged files: a NIfTI tensor volume written by nibabel with an unknown
datatype code (VTK 9.2's own NIfTI reader, which the tensor reader used to
call, dies with SIGSEGV on it), the same as .nii.gz, a .nii.gz whose gzip
stream is damaged, a .nii announcing 32767^3 voxels, a .tck cut inside a
point, a .trk whose header announces 2^31 - 1 streamlines, an .lr and a .g2
cut in half and a rational .g2.

    pvbatch TestPluginMalformedFiles.py <SplineVizPlugin library>
    pvpython TestPluginMalformedFiles.py --server <pvserver executable>

With --server a pvserver of the test's own is started (as in
TestPluginClientServer.py): the files are read and the tubes rendered there,
and the errors must appear in its log.
"""
import gzip
import os
import socket
import struct
import subprocess
import sys
import time

try:
    import nibabel as nib
    from dipy.data import get_fnames
    from nibabel.streamlines import Tractogram
except ImportError as error:
    print("nibabel or DIPY not available, skipped:", error)
    sys.exit(125)

import numpy as np
from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

import splineviz  # noqa: F401  (Python wrappers of the SplineViz classes)
from splineviz_testing import coverage, output_dir, white_view

out = output_dir()
source = os.environ["SPLINEVIZ_SOURCE_DIR"]
from splineviz_testing import Checker  # noqa: E402

checker = Checker()


check = checker.check


def write(name, data):
    path = os.path.join(out, "TestPluginMalformedFiles-" + name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def damaged_files():
    """(file, what the reader's error must say) for every kind of file."""
    files = []
    tensors = nib.Nifti1Image(np.ones((4, 3, 2, 1, 6), np.float32), np.diag([2.0, 2.0, 2.0, 1.0]))
    nib.save(tensors, os.path.join(out, "TestPluginMalformedFiles-good-tensors.nii"))
    good = open(os.path.join(out, "TestPluginMalformedFiles-good-tensors.nii"), "rb").read()
    bad = bytearray(good)
    struct.pack_into("<h", bad, 70, -1)  # datatype
    files.append((write("datatype.nii", bytes(bad)), "unknown datatype code -1"))
    files.append((write("datatype.nii.gz", gzip.compress(bytes(bad), mtime=0)),
                  "unknown datatype code -1"))
    gz = bytearray(gzip.compress(good, mtime=0))
    gz[-8] ^= 0xFF  # the CRC
    files.append((write("checksum.nii.gz", bytes(gz)), "incorrect data check"))
    huge = bytearray(good)
    struct.pack_into("<3h", huge, 42, 32767, 32767, 32767)
    files.append((write("huge.nii", bytes(huge)), "truncated"))
    cb = np.load(os.path.join(os.path.dirname(get_fnames("small_64D")[0]), "cb_2.npz"))
    lines = [cb["points"][s:e] for s, e in zip(np.r_[0, cb["offsets"][:-1]], cb["offsets"])]
    tck = os.path.join(out, "TestPluginMalformedFiles-good.tck")
    nib.streamlines.save(Tractogram(lines, affine_to_rasmm=np.eye(4)), tck)
    data = open(tck, "rb").read()
    files.append((write("cut.tck", data[:-7]), "truncated"))
    trk = os.path.join(out, "TestPluginMalformedFiles-good.trk")
    nib.streamlines.save(Tractogram(lines[:5], affine_to_rasmm=np.eye(4)), trk)
    trk_bytes = bytearray(open(trk, "rb").read())
    struct.pack_into("<i", trk_bytes, 988, 2**31 - 1)  # n_count
    files.append((write("count.trk", bytes(trk_bytes)), "n_count"))
    lr = open(os.path.join(source, "Testing", "Data", "External", "cube-3patch-refined.lr"), "rb").read()
    files.append((write("cut.lr", lr[: len(lr) // 2]), ""))
    g2 = open(os.path.join(source, "Testing", "Data", "External", "tensor-product-volume.g2"), "rb").read()
    files.append((write("cut.g2", g2[: len(g2) // 2]), ""))
    knots = g2.replace(b"0.25 0.375", b"0.375 0.25", 1)  # a decreasing knot vector
    files.append((write("knots.g2", knots), ""))
    return files, tck


def number_of_points(data):
    return 0 if data is None else data.GetNumberOfPoints()  # data sets and multiblocks


def start_server(pvserver):
    with socket.socket() as s:
        s.bind(("localhost", 0))
        port = s.getsockname()[1]
    env = dict(os.environ)
    env.pop("PV_PLUGIN_PATH", None)
    log_path = os.path.join(out, "TestPluginMalformedFiles-pvserver.log")
    log = open(log_path, "w")
    server = subprocess.Popen([pvserver, "--server-port=%d" % port], stdout=log,
                              stderr=subprocess.STDOUT, env=env)
    deadline = time.time() + 60
    while "Accepting connection" not in open(log_path).read():
        if server.poll() is not None or time.time() > deadline:
            print("ERROR: pvserver did not start (see %s)" % log_path)
            sys.exit(1)
        time.sleep(0.2)
    Connect("localhost", port)  # noqa: F405
    return server, log, log_path


remote = len(sys.argv) > 2 and sys.argv[1] == "--server"
server = None
if remote:
    server, log, log_path = start_server(sys.argv[2])
    from splineviz.plugin import load_plugin

    load_plugin(globals())
else:
    LoadPlugin(sys.argv[1], remote=False, ns=globals())

try:
    files, good_tck = damaged_files()
    view = white_view((400, 320))
    readers = []
    for path, expected in files:
        opened = [OpenDataFile(path)]  # noqa: F405  (File > Open's choice)
        if ".nii" in path:
            opened += [NIfTIDiffusionTensors(FileName=path), NIfTIVolume(FileName=path)]  # noqa: F405
        for reader in opened:
            name = "%s via %s" % (os.path.basename(path), reader.GetXMLName())
            logged = len(open(log_path).read()) if remote else 0
            reader.UpdatePipeline()
            display = Show(reader, view)  # noqa: F405  (what Apply does)
            Render(view)  # noqa: F405
            points = number_of_points(servermanager.Fetch(reader))
            if remote:
                # the server's new log lines: an error naming what is wrong
                new = open(log_path).read()[logged:]
                errors = [line for line in new.splitlines() if "ERR|" in line and expected in line]
                message = errors[0].split("ERR|")[1].strip() if errors else ""
                said = message != ""
            else:
                message = reader.GetClientSideObject().GetLastErrorMessage()
                said = message != "" and expected in message
            print("  %s: %s" % (name, message or "(see the server's log)"))
            check(points == 0 and said, name + ": refused with its error, an empty output")
            Hide(reader, view)  # noqa: F405
            readers.append(reader)

    # The same session: a good tractogram still renders.
    fibres = OpenDataFile(good_tck)  # noqa: F405
    tubes = Show(fibres, view)  # noqa: F405
    tubes.SetRepresentationType("Ray-Cast Tubes")
    tubes.TubeRadius = 0.6
    ResetCamera(view)  # noqa: F405
    cover, _ = coverage(view, "TestPluginMalformedFiles%s.png" % ("-server" if remote else ""))
    print("the good tractogram after the damaged files: coverage %.3f" % cover)
    check(fibres.GetXMLName() == "TractogramReader" and cover > 0.03,
          "after every damaged file, a good tractogram renders as ray-cast tubes in the same session")
    if remote:
        Disconnect()  # noqa: F405
finally:
    if server is not None:
        server.terminate()
        try:
            server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            server.kill()
        log.close()

checker.finish()
print("ParaView survives every damaged file")
