"""Drives the real editor with xdotool like a user (mouse and keys only) and reads back what it
reports with --debug-state: pointer presses as the editor saw them, status messages, and after
every change its state at rest (document counts, where each vertex, edge, face and normal knob
is on screen, the view's projection). Every step waits for the editor to report its effect, never
for a fixed time, so the tests hold on a loaded machine.
"""
import os
import re
import subprocess
import time

TIMEOUT = float(os.environ.get("E2E_TIMEOUT", "60"))
# xdotool's buttons (1 left, 2 middle, 3 right) as the editor (ImGui) numbers them.
IMGUI_BUTTON = {1: 0, 2: 2, 3: 1}


class EditorError(Exception):
    pass


def xdo(*args):
    subprocess.run(["xdotool", *[str(a) for a in args]], check=True)


def check(condition, message):
    if not condition:
        raise EditorError("FAIL: " + message)


def shot(name):
    """With E2E_SHOTS=DIR, a screenshot of the screen as it is now (for looking at the steps)."""
    if os.environ.get("E2E_SHOTS"):
        time.sleep(0.5)  # a frame or two for the hover; only pictures depend on it
        subprocess.run(["import", "-window", "root", os.path.join(os.environ["E2E_SHOTS"],
                                                                   name + ".png")], check=True)


class State:
    """One state report: counts, tool and the window pixels of everything clickable."""

    def __init__(self, lines):
        counts, tool = lines[0].split(" tool ", 1)  # the tool's name is last and may have spaces
        head = counts.split()
        self.fields = {head[i]: head[i + 1] for i in range(1, len(head) - 1, 2)}
        self.fields["tool"] = tool
        self.revision = int(self.fields["revision"])
        self.vertices, self.edges, self.faces, self.knobs = {}, {}, {}, {}
        self.curves = {}  # free curve -> a pixel on its line that picks it
        self.joints = []  # (curve, curve, "G0" | "G1" | "G2", gap, angle in degrees, jump)
        self.curve_points = {}  # (curve, point) -> pixel
        self.free_points = {}  # (face, "centre" or "S,J,K") -> pixel of a GB face's free point
        for line in lines[1:]:
            w = line.split()
            if w[0] == "view":
                nums = [float(x) for x in w[1:9]]
                self.origin = nums[0:2]
                self.axes = [nums[2:4], nums[4:6], nums[6:8]]
                self.window = (int(w[10]), int(w[11]))
            elif w[0] in ("vertex", "edge", "face", "knob", "curve"):
                where = None if w[2] == "hidden" else (float(w[2]), float(w[3]))
                table = {"vertex": self.vertices, "edge": self.edges, "face": self.faces,
                         "knob": self.knobs, "curve": self.curves}[w[0]]
                table[int(w[1])] = where
            elif w[0] == "free-point":
                self.free_points[(int(w[1]), w[2])] = (
                    None if w[3] == "hidden" else (float(w[3]), float(w[4])))
            elif w[0] == "joint":
                self.joints.append((int(w[1]), int(w[2]), w[3], float(w[5]), float(w[7]),
                                    float(w[9])))
            elif w[0] == "curve-point":
                self.curve_points[(int(w[1]), int(w[2]))] = (
                    None if w[3] == "hidden" else (float(w[3]), float(w[4])))

    def count(self, what):
        return int(self.fields[what])

    @property
    def tool(self):
        return self.fields["tool"]

    def world_to_pixel(self, p):
        """Window pixel of world point p (exact in an orthographic view: the map is affine)."""
        x, y = self.origin
        for k in range(3):
            x += p[k] * (self.axes[k][0] - self.origin[0])
            y += p[k] * (self.axes[k][1] - self.origin[1])
        return x, y


class Editor:
    def __init__(self, binary, args, workdir, env):
        self.log_path = os.path.join(workdir, "editor.log")
        self.err_path = os.path.join(workdir, "editor.err")
        self.log = open(self.log_path, "w")
        self.err = open(self.err_path, "w")
        self.proc = subprocess.Popen([binary, *args, "--debug-state"], cwd=os.path.join(workdir, "cwd"),
                                     stdout=self.log, stderr=self.err, env=env)
        self.seen = 0  # wait_line() looks at the log from here: where the last action began
        self.window = None

    # `with ed:` around a test's steps: on a failure the editor is stopped and the end of its log
    # printed, then the failure goes on.
    def __enter__(self):
        return self

    def __exit__(self, kind, value, trace):
        if kind is not None:
            if self.proc.poll() is None:
                self.proc.kill()
            print("\n".join(self.lines()[-40:]))
        return False

    # --- reading the log -------------------------------------------------------------------
    def lines(self):
        with open(self.log_path) as f:
            return f.read().splitlines()

    def wait_line(self, pattern, what=None, since=None):
        """Waits for a log line matching `pattern` from line `since` on (default: the line the
        last action began at, so whatever it caused is found in any order); returns its match."""
        start = self.seen if since is None else since
        rx = re.compile(pattern)
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            lines = self.lines()
            for i in range(start, len(lines)):
                m = rx.search(lines[i])
                if m:
                    return m
            if self.proc.poll() is not None:
                raise EditorError(f"the editor exited ({self.proc.returncode}) waiting for "
                                  f"{what or pattern}:\n" + open(self.err_path).read())
            time.sleep(0.05)
        raise EditorError(f"timed out waiting for {what or pattern}; log tail:\n" +
                          "\n".join(self.lines()[-30:]))

    def states(self):
        """Every complete state report in the log, in order."""
        out, block = [], None
        for line in self.lines():
            if line.startswith("state revision"):
                block = [line]
            elif block is not None:
                if line.startswith("state-end"):
                    out.append(State(block))
                    block = None
                else:
                    block.append(line)
        return out

    def state(self):
        s = self.states()
        if not s:
            raise EditorError("no state reported yet")
        return s[-1]

    def wait_state(self, predicate, what):
        """Waits for a state report (the latest one) that satisfies `predicate`."""
        deadline = time.time() + TIMEOUT
        while time.time() < deadline:
            s = self.states()
            if s and predicate(s[-1]):
                self.window = s[-1].window
                return s[-1]
            if self.proc.poll() is not None:
                raise EditorError(f"the editor exited waiting for {what}:\n" +
                                  open(self.err_path).read())
            time.sleep(0.05)
        last = self.states()[-1].fields if self.states() else None
        raise EditorError(f"timed out waiting for {what}; last state {last}")

    def mark(self):
        """The number of state reports so far: take it before acting, then wait_change(mark)."""
        return len(self.states())

    def wait_change(self, mark, what, predicate=lambda s: True):
        """Waits for a state report after `mark` (see mark()) that satisfies `predicate`."""
        def newer(s):
            return len(self.states()) > mark and predicate(s)
        return self.wait_state(newer, what)

    # --- acting ------------------------------------------------------------------------------
    def focus(self):
        """Gives the editor's window the keyboard (Xvfb has no window manager to do it)."""
        wid = subprocess.run(["xdotool", "search", "--sync", "--pid", str(self.proc.pid)],
                             capture_output=True, text=True, check=True).stdout.split()[0]
        subprocess.run(["xdotool", "windowfocus", "--sync", wid], stderr=subprocess.DEVNULL)

    def new_scene(self):
        """File > New (an empty network, framed iso), then the orthographic view, where window
        pixels map to the work plane affinely. Returns the state in that view."""
        self.key("ctrl+n")
        self.wait_state(lambda s: s.count("vertices") == 0 and s.count("edges") == 0 and
                        s.count("curves") == 0 and not int(s.fields["can-undo"]), "an empty scene")
        mark = self.mark()
        self.key("5")
        return self.wait_change(mark, "the orthographic view")

    def panel_item(self, label):
        """The latest reported centre of a side-panel item (printed when it appears or moves)."""
        self.wait_line(rf"^panel-item {label} ", label, since=0)
        rx = re.compile(rf"^panel-item {label} ([0-9.]+) ([0-9.]+) window")
        last = [m for m in map(rx.match, self.lines()) if m][-1]
        return float(last.group(1)), float(last.group(2))

    def tool(self, key, name):
        """Picks a tool by its key; returns the state once the editor reports it active."""
        self.key(key)
        return self.wait_state(lambda s: s.tool == name, f"the {name} tool")

    def _act(self):
        """Marks where the next action begins in the log (see wait_line)."""
        self.seen = len(self.lines())
        return self.seen

    def screen(self, p):
        return int(round(self.window[0] + p[0])), int(round(self.window[1] + p[1]))

    def move(self, p):
        x, y = self.screen(p)
        xdo("mousemove", x, y)
        return x, y

    def press(self, p, button=1):
        """Moves there and presses; returns once the editor saw the press there."""
        x, y = self.move(p)
        # The editor logs the cursor only while a button is held: give it a few frames to see
        # the move first, or a press landing in the same frame counts as a drag from the old
        # position (a right-click then opens no menu, a click becomes a camera gesture).
        time.sleep(0.2)
        mark = self._act()
        xdo("mousedown", button)
        self.wait_line(rf"^pointer down {IMGUI_BUTTON[button]} ",
                       f"press of button {button}", since=mark)
        return x, y

    def drag_to(self, p):
        """Moves the held mouse and waits until the editor saw the cursor there."""
        mark = len(self.lines())
        x, y = self.move(p)
        px, py = x - self.window[0], y - self.window[1]
        self.wait_line(rf"^pointer at {px} {py}$", f"the cursor at {px} {py}", since=mark)

    def release(self, button=1):
        mark = len(self.lines())
        xdo("mouseup", button)
        self.wait_line(rf"^pointer up {IMGUI_BUTTON[button]} ",
                       f"release of button {button}", since=mark)

    def click(self, p, button=1):
        self.press(p, button)
        self.release(button)

    def key(self, *keys):
        self._act()
        xdo("key", *keys)

    def shortcut(self, *keys):
        """A key chord for the editor's commands: waits until no text field or popup holds the
        keyboard (the editor drops shortcuts pressed meanwhile; a dialog closes a frame after its
        button), then sends it."""
        self.wait_state(lambda s: s.fields.get("keys") == "1", "the editor to take shortcuts")
        self.key(*keys)

    def hold(self, key):
        self._act()
        xdo("keydown", key)

    def let_go(self, key):
        xdo("keyup", key)

    def type_text(self, text):
        self._act()
        xdo("type", "--delay", 30, text)

    def quit(self):
        self.key("ctrl+q")
        try:
            self.proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            raise EditorError("the editor did not quit")
