import java.lang.reflect.*;
import java.math.*;
import java.nio.file.*;
import java.util.*;

public class ApiDiff {
    static class L extends ClassLoader {
        final byte[] bytes;
        L(byte[] b, ClassLoader p) { super(p); bytes = b; }
        protected Class<?> loadClass(String n, boolean r) throws ClassNotFoundException {
            if (n.equals("org.fclcert.eval.Rational")) synchronized (this) {
                Class<?> c = findLoadedClass(n); if (c == null) c = defineClass(n, bytes, 0, bytes.length); return c; }
            return super.loadClass(n, r);
        }
    }
    static class R {
        Class<?> c; Map<String, Method> m = new HashMap<>(); Object ZERO, ONE, HALF, TWO;
        R(byte[] b) throws Exception {
            c = new L(b, ApiDiff.class.getClassLoader()).loadClass("org.fclcert.eval.Rational");
            for (Method x : c.getDeclaredMethods()) { x.setAccessible(true); m.put(x.getName() + x.getParameterCount() + (x.getParameterCount() > 0 ? x.getParameterTypes()[0].getSimpleName() : ""), x); }
            for (String f : new String[]{"ZERO", "ONE", "HALF", "TWO"}) { Field fl = c.getDeclaredField(f); fl.setAccessible(true); }
            ZERO = get("ZERO"); ONE = get("ONE"); HALF = get("HALF"); TWO = get("TWO");
        }
        Object get(String f) throws Exception { Field fl = c.getDeclaredField(f); fl.setAccessible(true); return fl.get(null); }
        Object call(String k, Object t, Object... a) {
            Method x = m.get(k);
            if (x == null) { return "absent"; }   // a method the class no longer has (hasExactSqrt since c27r)
            try { return x.invoke(t, a); }
            catch (InvocationTargetException e) { return "EXC:" + e.getCause().getClass().getSimpleName() + ":" + e.getCause().getMessage(); }
            catch (Exception e) { throw new RuntimeException(k, e); }
        }
    }
    static String val(R r, Object o) {   // value as reduced fraction, independent of the representation
        if (!(r.c.isInstance(o))) return String.valueOf(o);
        try {
            Field n = r.c.getDeclaredField("num"), d = r.c.getDeclaredField("den"); n.setAccessible(true); d.setAccessible(true);
            BigInteger p = (BigInteger) n.get(o), q = (BigInteger) d.get(o);
            if (q.signum() == 0) return "BAD:" + p + "/0";
            BigInteger g = p.gcd(q); if (g.signum() == 0) g = BigInteger.ONE;
            if (q.signum() < 0) { p = p.negate(); q = q.negate(); }
            return p.divide(g) + "/" + q.divide(g) + (g.equals(BigInteger.ONE) ? "" : "[unreduced]");
        } catch (Exception e) { throw new RuntimeException(e); }
    }
    static List<String> run(R r, long seed) {
        Random rnd = new Random(seed);
        List<String> out = new ArrayList<>();
        List<Object> pool = new ArrayList<>(List.of(r.ZERO, r.ONE, r.HALF, r.TWO));
        for (int i = 0; i < 400; i++) {
            int kind = rnd.nextInt(6);
            BigInteger p, q;
            switch (kind) {
                case 0 -> { p = BigInteger.valueOf(rnd.nextInt(21) - 10); q = BigInteger.valueOf(rnd.nextInt(12) + 1); }
                case 1 -> { p = BigInteger.valueOf(rnd.nextInt(2001) - 1000); q = BigInteger.TEN.pow(rnd.nextInt(5)); }
                case 2 -> { p = BigInteger.valueOf(rnd.nextInt(7) * rnd.nextInt(7)); q = BigInteger.valueOf((rnd.nextInt(5) + 1) * (rnd.nextInt(5) + 1)); }
                case 3 -> { p = new BigInteger(90, rnd).subtract(BigInteger.ONE.shiftLeft(89)); q = new BigInteger(80, rnd).add(BigInteger.ONE); }
                case 4 -> { p = BigInteger.valueOf(rnd.nextInt(9) - 4); q = BigInteger.valueOf(rnd.nextBoolean() ? 1 : -2); }
                default -> { p = BigInteger.valueOf(rnd.nextInt(5) - 2); q = BigInteger.valueOf(rnd.nextInt(5) - 2); }
            }
            Object x = r.call("of2BigInteger", null, p, q);
            out.add("of " + p + "/" + q + " = " + val(r, x));
            if (r.c.isInstance(x)) pool.add(x);
        }
        long[] longs = {0, 1, -1, 2, 7, -13, 1L << 40};
        for (long n : longs) { Object x = r.call("of1long", null, n); out.add("ofl " + n + " = " + val(r, x)); pool.add(x); }
        double[] ds = {0.0, -0.0, 1.0, -1.0, 0.1, 0.3, 2.5, 1e-300, 1e308, 123.456, Double.MIN_VALUE, 0.21, 2.79};
        for (double d : ds) {
            Object x = r.call("exactly1double", null, d); out.add("exactly " + d + " = " + val(r, x)); pool.add(x);
            Object y = r.call("decimal1double", null, d); out.add("decimal " + d + " = " + val(r, y)); pool.add(y);
            out.add("bd " + d + " = " + r.call("of1BigDecimal", null, new BigDecimal(Double.toString(d))).toString().length());
        }
        for (BigDecimal bd : new BigDecimal[]{new BigDecimal("1E+3"), new BigDecimal("25"), new BigDecimal("0.125"), new BigDecimal("-3E-2")}) {
            Object x = r.call("of1BigDecimal", null, bd); out.add("of(bd) " + bd + " = " + val(r, x)); pool.add(x);
        }
        for (int i = 0; i < 3000; i++) {
            Object a = pool.get(rnd.nextInt(pool.size())), b = rnd.nextInt(5) == 0 ? a : pool.get(rnd.nextInt(pool.size()));
            String s = val(r, a) + " , " + val(r, b) + " : ";
            Object add = r.call("add1Rational", a, b), sub = r.call("subtract1Rational", a, b), mul = r.call("multiply1Rational", a, b),
                    div = r.call("divide1Rational", a, b);
            out.add(s + "add " + val(r, add) + " sub " + val(r, sub) + " mul " + val(r, mul) + " div " + val(r, div)
                    + " cmp " + r.call("compareTo1Rational", a, b) + " eq " + r.call("equals1Object", a, b)
                    + " min " + val(r, r.call("min1Rational", a, b)) + " max " + val(r, r.call("max1Rational", a, b)));
            out.add(val(r, a) + " : neg " + val(r, r.call("negate0", a)) + " abs " + val(r, r.call("abs0", a)) + " clamp " + val(r, r.call("clamp010", a))
                    + " zero " + r.call("isZero0", a) + " sgn " + r.call("signum0", a) + " round " + val(r, r.call("roundHalfAwayFromZero0", a))
                    + " sqrt " + val(r, r.call("sqrt0", a)) + " hasSqrt " + r.call("hasExactSqrt0", a) + " dbl " + r.call("toDouble0", a));
            if (r.c.isInstance(add) && rnd.nextInt(3) == 0 && pool.size() < 2000) pool.add(add);
            if (r.c.isInstance(mul) && rnd.nextInt(3) == 0 && pool.size() < 2000) pool.add(mul);
        }
        return out;
    }
    public static void main(String[] a) throws Exception {
        R o = new R(Files.readAllBytes(Path.of(a[0])));
        List<String> ref = run(o, 7);
        for (int k = 1; k < a.length; k++) {
            Path dir = Path.of(a[k]);
            R m;
            try { m = new R(Files.readAllBytes(dir.resolve("org.fclcert.eval.Rational.class"))); } catch (Throwable t) { System.out.println(dir.getFileName() + " LOADFAIL " + t); continue; }
            List<String> got;
            try { got = run(m, 7); } catch (Throwable t) { System.out.println(dir.getFileName() + " CRASH " + t); continue; }
            int diff = 0; String ex = "";
            for (int i = 0; i < Math.min(ref.size(), got.size()); i++) if (!ref.get(i).equals(got.get(i))) { if (diff++ == 0) ex = ref.get(i) + "  ||  " + got.get(i); }
            System.out.println(dir.getFileName() + " diffs " + diff + "/" + ref.size() + (diff > 0 ? " e.g. " + (ex.length() > 300 ? ex.substring(0, 300) : ex) : ""));
        }
    }
}
