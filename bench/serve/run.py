"""glint-serve against glint render, in one run: how soon a page sees a picture after a camera
move (the preview), and how long the page's whole render takes against `glint render` of the
same view with the same threads.

    python3 bench/serve/run.py [--scene scenes/showcase.yaml] [--moves 10] [--repeat 3]

Each move orbits the camera a little; the first picture is the first frame event of the new
view, counted from the moment the move is sent; the whole render ends with the frame whose
passes are all done. glint render renders the scene's own view, which costs the same."""

import argparse
import http.client
import json
import math
import pathlib
import re
import statistics
import subprocess
import threading
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]


class Page:
    """An event stream read on a thread: each frame event with the moment it came."""

    def __init__(self, port):
        self.port = port
        self.frames = []
        self.session = None
        self.ready = threading.Event()
        self.lock = threading.Lock()
        threading.Thread(target=self.read, daemon=True).start()
        self.ready.wait(10)

    def read(self):
        connection = http.client.HTTPConnection("127.0.0.1", self.port)
        connection.request("GET", "/events")
        response = connection.getresponse()
        name = None
        while True:
            line = response.fp.readline().decode()
            if not line:
                return
            if line.startswith("event: "):
                name = line[7:].strip()
            elif line.startswith("data: "):
                data = json.loads(line[6:])
                if name == "hello":
                    self.session = data["session"]
                    self.camera = data["camera"]
                    self.ready.set()
                else:
                    with self.lock:
                        self.frames.append((time.perf_counter(), data))

    def post(self, path, body=""):
        connection = http.client.HTTPConnection("127.0.0.1", self.port)
        connection.request("POST", f"{path}?session={self.session}", body)
        answer = json.loads(connection.getresponse().read())
        return answer

    def wait_for(self, condition, timeout=600):
        end = time.time() + timeout
        while time.time() < end:
            with self.lock:
                for moment, frame in self.frames:
                    if condition(frame):
                        return moment, frame
            time.sleep(0.001)
        raise TimeoutError


def orbit(camera, angle):
    """The camera turned by angle (radians) about the vertical through what it looks at."""
    fx, fy, fz = (f - a for f, a in zip(camera["from"], camera["at"]))
    c, s = math.cos(angle), math.sin(angle)
    moved = dict(camera)
    moved["from"] = [camera["at"][0] + c * fx + s * fz, camera["at"][1] + fy,
                     camera["at"][2] - s * fx + c * fz]
    return {k: moved[k] for k in ("type", "from", "at", "up", "fov")}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", default=str(ROOT / "scenes/showcase.yaml"))
    parser.add_argument("--serve", default=str(ROOT / "build/release/apps/glint-serve/glint-serve"))
    parser.add_argument("--glint", default=str(ROOT / "build/release/apps/glint/glint"))
    parser.add_argument("--moves", type=int, default=10)
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()

    server = subprocess.Popen([args.serve, args.scene, "--port", "0"], stdout=subprocess.PIPE,
                              text=True)
    port = int(re.search(r":(\d+)/", server.stdout.readline()).group(1))
    page = Page(port)
    page.wait_for(lambda f: not f["preview"] and f["passes_done"] == f["passes_total"])

    first_pictures = []
    for move in range(args.moves):
        sent = time.perf_counter()
        version = page.post("/camera", json.dumps(orbit(page.camera, 0.02 * (move + 1))))["version"]
        moment, _ = page.wait_for(lambda f: f["version"] >= version)
        first_pictures.append(moment - sent)

    whole_page, whole_render = [], []
    for _ in range(args.repeat):
        sent = time.perf_counter()
        version = page.post("/camera/reset")["version"]
        moment, _ = page.wait_for(lambda f: f["version"] >= version and not f["preview"] and
                                  f["passes_done"] == f["passes_total"])
        whole_page.append(moment - sent)
        with page.lock:
            frames = sum(1 for _, f in page.frames if f["version"] == version)
        start = time.perf_counter()
        subprocess.run([args.glint, "render", args.scene, "-o", "/tmp/glint-serve-bench.png",
                        "--quiet"], check=True)
        whole_render.append(time.perf_counter() - start)
    server.terminate()
    server.wait()

    print(f"scene {pathlib.Path(args.scene).name}")
    print(f"first picture after a move: median {statistics.median(first_pictures) * 1e3:.0f} ms, "
          f"worst {max(first_pictures) * 1e3:.0f} ms over {args.moves} moves")
    page_time, render_time = min(whole_page), min(whole_render)
    print(f"whole render: page {page_time:.2f} s, glint render {render_time:.2f} s "
          f"(process included), ratio {page_time / render_time:.3f}; the page was sent {frames} "
          f"frames of the last, preview included")


if __name__ == "__main__":
    main()
