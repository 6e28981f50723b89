// xdnd_drop WINDOW X Y FILE: drops FILE onto X window WINDOW at root
// position (X, Y) the way a file manager does, through the XDND protocol
// (freedesktop.org XDND version 5): enter, position, wait for the target's
// status, drop, hand over the file as text/uri-list, wait for finished.
// xdotool moves the pointer and clicks but cannot drag data between
// programs; this is the source side of a real drag, for the studio's tests.
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

namespace {

Display* dpy = nullptr;
Window source = 0, target = 0;

Atom atom(const char* name) { return XInternAtom(dpy, name, False); }

void send(const char* type, long l1, long l2, long l3, long l4) {
  XEvent e{};
  e.xclient.type = ClientMessage;
  e.xclient.display = dpy;
  e.xclient.window = target;
  e.xclient.message_type = atom(type);
  e.xclient.format = 32;
  e.xclient.data.l[0] = static_cast<long>(source);
  e.xclient.data.l[1] = l1;
  e.xclient.data.l[2] = l2;
  e.xclient.data.l[3] = l3;
  e.xclient.data.l[4] = l4;
  XSendEvent(dpy, target, False, NoEventMask, &e);
  XFlush(dpy);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: xdnd_drop WINDOW X Y FILE\n");
    return 2;
  }
  dpy = XOpenDisplay(nullptr);
  if (!dpy) {
    std::fprintf(stderr, "xdnd_drop: cannot open the display\n");
    return 1;
  }
  target = static_cast<Window>(std::strtoul(argv[1], nullptr, 0));
  const long x = std::atol(argv[2]), y = std::atol(argv[3]);
  const std::string uri = "file://" + std::filesystem::absolute(argv[4]).string() + "\r\n";
  source = XCreateSimpleWindow(dpy, DefaultRootWindow(dpy), 0, 0, 1, 1, 0, 0, 0);
  XSetSelectionOwner(dpy, atom("XdndSelection"), source, CurrentTime);
  const Atom uri_list = atom("text/uri-list");
  send("XdndEnter", 5L << 24, static_cast<long>(uri_list), 0, 0);
  send("XdndPosition", 0, (x << 16) | y, CurrentTime, static_cast<long>(atom("XdndActionCopy")));
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  bool dropped = false;
  while (std::chrono::steady_clock::now() < end) {
    if (!XPending(dpy)) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      continue;
    }
    XEvent e;
    XNextEvent(dpy, &e);
    if (e.type == ClientMessage && e.xclient.message_type == atom("XdndStatus")) {
      if (!(e.xclient.data.l[1] & 1)) {
        std::fprintf(stderr, "xdnd_drop: the window refuses the drop\n");
        return 1;
      }
      if (!dropped) send("XdndDrop", 0, CurrentTime, 0, 0);
      dropped = true;
    } else if (e.type == SelectionRequest) {
      // The target asks for the data: the file's URI on the property it names.
      const XSelectionRequestEvent& r = e.xselectionrequest;
      XEvent reply{};
      reply.xselection.type = SelectionNotify;
      reply.xselection.display = dpy;
      reply.xselection.requestor = r.requestor;
      reply.xselection.selection = r.selection;
      reply.xselection.target = r.target;
      reply.xselection.time = r.time;
      reply.xselection.property = None;
      if (r.target == uri_list) {
        XChangeProperty(dpy, r.requestor, r.property, uri_list, 8, PropModeReplace, reinterpret_cast<const unsigned char*>(uri.data()),
                        static_cast<int>(uri.size()));
        reply.xselection.property = r.property;
      }
      XSendEvent(dpy, r.requestor, False, NoEventMask, &reply);
      XFlush(dpy);
    } else if (e.type == ClientMessage && e.xclient.message_type == atom("XdndFinished")) {
      XCloseDisplay(dpy);
      return 0;
    }
  }
  std::fprintf(stderr, "xdnd_drop: no %s from the window within 10 s\n", dropped ? "XdndFinished" : "XdndStatus");
  return 1;
}
