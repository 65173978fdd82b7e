#include "xdnd_source.h"

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <poll.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>

namespace prism::test {
namespace {

using Clock = std::chrono::steady_clock;

// Xlib's default error handler ends the process; a test must fail instead.
int ignoreXError(Display*, XErrorEvent*) { return 0; }

// A file URI as text/uri-list carries it: every byte outside the unreserved
// set (and '/') percent-encoded.
std::string fileUri(const std::filesystem::path& path) {
  std::string uri = "file://";
  for (const unsigned char c : std::filesystem::absolute(path).string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      uri += char(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      uri += hex;
    }
  }
  return uri;
}

struct DisplayCloser {
  void operator()(Display* d) const { XCloseDisplay(d); }
};

// The XDND version a window accepts drops of, 0 if it accepts none.
long xdndVersion(Display* d, Window w, Atom xdndAware) {
  Atom type = None;
  int format = 0;
  unsigned long count = 0, after = 0;
  unsigned char* data = nullptr;
  long version = 0;
  if (XGetWindowProperty(d, w, xdndAware, 0, 1, False, XA_ATOM, &type, &format, &count, &after,
                         &data) == Success &&
      data && count == 1 && format == 32)
    version = long(*reinterpret_cast<Atom*>(data));
  if (data) XFree(data);
  return version;
}

} // namespace

bool dropFiles(const std::string& displayName, const std::vector<std::filesystem::path>& files,
               int x, int y, double seconds) {
  XSetErrorHandler(ignoreXError);
  const std::unique_ptr<Display, DisplayCloser> owned(XOpenDisplay(displayName.c_str()));
  Display* d = owned.get();
  if (!d) return false;
  const Window root = DefaultRootWindow(d);
  const auto atom = [&](const char* name) { return XInternAtom(d, name, False); };
  const Atom aware = atom("XdndAware"), enter = atom("XdndEnter"), position = atom("XdndPosition"),
             status = atom("XdndStatus"), drop = atom("XdndDrop"), finished = atom("XdndFinished"),
             leave = atom("XdndLeave"), selection = atom("XdndSelection"),
             copy = atom("XdndActionCopy"), uriList = atom("text/uri-list");

  // The target: a viewable top-level window that takes drops.
  Window target = None;
  long version = 0;
  Window rootReturn = None, parent = None, *children = nullptr;
  unsigned int count = 0;
  if (XQueryTree(d, root, &rootReturn, &parent, &children, &count)) {
    for (unsigned int i = count; i-- > 0 && target == None;) { // topmost first
      XWindowAttributes attributes;
      if (!XGetWindowAttributes(d, children[i], &attributes) || attributes.map_state != IsViewable)
        continue;
      if (const long v = xdndVersion(d, children[i], aware); v > 0) {
        target = children[i];
        version = std::min(v, 5L);
      }
    }
    if (children) XFree(children);
  }
  if (target == None) return false;

  const Window source = XCreateSimpleWindow(d, root, 0, 0, 1, 1, 0, 0, 0);
  XSetSelectionOwner(d, selection, source, CurrentTime);
  if (XGetSelectionOwner(d, selection) != source) return false;
  int rootX = 0, rootY = 0;
  Window child = None;
  XTranslateCoordinates(d, target, root, x, y, &rootX, &rootY, &child);

  std::string uris;
  for (const std::filesystem::path& f : files)
    uris += fileUri(f) + "\r\n";

  const auto send = [&](Atom type, long l1, long l2, long l3, long l4) {
    XEvent e{};
    e.xclient.type = ClientMessage;
    e.xclient.display = d;
    e.xclient.window = target;
    e.xclient.message_type = type;
    e.xclient.format = 32;
    e.xclient.data.l[0] = long(source);
    e.xclient.data.l[1] = l1;
    e.xclient.data.l[2] = l2;
    e.xclient.data.l[3] = l3;
    e.xclient.data.l[4] = l4;
    XSendEvent(d, target, False, NoEventMask, &e);
    XFlush(d);
  };
  // Serves the selection's data to whoever asks; true when `done` holds
  // for an event before the deadline.
  const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
  const auto waitFor = [&](const std::function<bool(const XEvent&)>& done) {
    for (;;) {
      while (XPending(d)) {
        XEvent e;
        XNextEvent(d, &e);
        if (e.type == SelectionRequest && e.xselectionrequest.selection == selection) {
          const XSelectionRequestEvent& request = e.xselectionrequest;
          XEvent reply{};
          reply.xselection.type = SelectionNotify;
          reply.xselection.display = d;
          reply.xselection.requestor = request.requestor;
          reply.xselection.selection = request.selection;
          reply.xselection.target = request.target;
          reply.xselection.time = request.time;
          reply.xselection.property = None;
          if (request.target == uriList && request.property != None) {
            XChangeProperty(d, request.requestor, request.property, uriList, 8, PropModeReplace,
                            reinterpret_cast<const unsigned char*>(uris.data()), int(uris.size()));
            reply.xselection.property = request.property;
          }
          XSendEvent(d, request.requestor, False, NoEventMask, &reply);
          XFlush(d);
        }
        if (done(e)) return true;
      }
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      pollfd p{ConnectionNumber(d), POLLIN, 0};
      poll(&p, 1, int(left));
    }
  };
  const auto message = [](const XEvent& e, Atom type) {
    return e.type == ClientMessage && e.xclient.message_type == type;
  };

  send(enter, version << 24, long(uriList), long(None), long(None));
  send(position, 0, (long(rootX) << 16) | long(rootY & 0xffff), long(CurrentTime), long(copy));
  bool accepted = false;
  if (!waitFor([&](const XEvent& e) {
        if (!message(e, status)) return false;
        accepted = (e.xclient.data.l[1] & 1) != 0;
        return true;
      }) ||
      !accepted) {
    send(leave, 0, 0, 0, 0);
    return false;
  }
  send(drop, 0, long(CurrentTime), 0, 0);
  bool done = false;
  waitFor([&](const XEvent& e) {
    if (!message(e, finished)) return false;
    done = version < 5 || (e.xclient.data.l[1] & 1) != 0;
    return true;
  });
  XDestroyWindow(d, source);
  return done;
}

} // namespace prism::test
