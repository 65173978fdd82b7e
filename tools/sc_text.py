"""Writing .sc text from Python: what the scene generators (chex_gen.py,
glass_gen.py) share. Numbers are printed with six significant digits and
never as -0, so a regenerated scene is byte-identical on every platform."""
import os


def scene_path(name):
    """The path of scenes/NAME beside this tools/ folder."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', name)


def num(x):
    s = '%.6g' % x
    return '0' if s in ('-0', '0') else s


def point(v):
    return ' '.join(num(c) for c in v)


def polygon(vs, indent='  '):
    """A `polygon` command over the vertices vs, on a line of its own."""
    return indent + 'polygon %d  ' % len(vs) + '  '.join(point(v) for v in vs) + '\n'
