import java.io.*;
import java.lang.reflect.*;
import java.math.*;
import java.nio.file.*;
import java.util.*;

public class ConversionDiff {
    static class L extends ClassLoader {
        final byte[] bytes;
        L(byte[] b, ClassLoader parent) { super(parent); bytes = b; }
        protected Class<?> loadClass(String n, boolean r) throws ClassNotFoundException {
            if (n.equals("org.fclcert.eval.Rational")) {
                synchronized (this) {
                    Class<?> c = findLoadedClass(n);
                    if (c == null) c = defineClass(n, bytes, 0, bytes.length);
                    return c;
                }
            }
            return super.loadClass(n, r);
        }
    }
    static Method of2, toD, sd, dec;
    static class R { Method of2, toD, sd; Class<?> c; }
    static R load(byte[] b) throws Exception {
        R r = new R();
        r.c = new L(b, ConversionDiff.class.getClassLoader()).loadClass("org.fclcert.eval.Rational");
        r.of2 = r.c.getDeclaredMethod("of", BigInteger.class, BigInteger.class); r.of2.setAccessible(true);
        r.toD = r.c.getDeclaredMethod("toDouble"); r.toD.setAccessible(true);
        r.sd = r.c.getDeclaredMethod("shortestDecimal", double.class); r.sd.setAccessible(true);
        return r;
    }
    static double td(R r, BigInteger p, BigInteger q) {
        try { return (double) r.toD.invoke(r.of2.invoke(null, p, q)); }
        catch (InvocationTargetException e) { return Double.NaN; }
        catch (Exception e) { throw new RuntimeException(e); }
    }
    static long ulps(double a, double b) {
        if (Double.isNaN(a) || Double.isNaN(b)) return (Double.isNaN(a) && Double.isNaN(b)) ? 0 : Long.MAX_VALUE;
        if (a == b) return 0;
        if (Double.isInfinite(a) || Double.isInfinite(b)) return Long.MAX_VALUE - 1;
        return Math.abs(ord(a) - ord(b));
    }
    static long ord(double d) { long b = Double.doubleToLongBits(d); return b >= 0 ? b : -(b & Long.MAX_VALUE); }
    public static void main(String[] a) throws Exception {
        R orig = load(Files.readAllBytes(Path.of(a[0])));
        Random rnd = new Random(42);
        List<BigInteger[]> vals = new ArrayList<>();
        // random rationals of many sizes, both signs
        for (int i = 0; i < 20000; i++) {
            int pb = 1 + rnd.nextInt(rnd.nextBoolean() ? 70 : 400), qb = 1 + rnd.nextInt(rnd.nextBoolean() ? 70 : 400);
            BigInteger p = new BigInteger(pb, rnd).add(BigInteger.ONE), q = new BigInteger(qb, rnd).add(BigInteger.ONE);
            if (rnd.nextInt(4) == 0) p = p.negate();
            vals.add(new BigInteger[]{p, q});
        }
        // decimals a/10^k, integers, halves, tiny and huge
        for (int i = 0; i < 5000; i++) {
            BigInteger p = BigInteger.valueOf(rnd.nextInt(2000000) - 1000000);
            vals.add(new BigInteger[]{p, BigInteger.TEN.pow(rnd.nextInt(8))});
            vals.add(new BigInteger[]{p, BigInteger.ONE});
            vals.add(new BigInteger[]{p, BigInteger.ONE.shiftLeft(rnd.nextInt(80))});
            vals.add(new BigInteger[]{p, BigInteger.TEN.pow(300 + rnd.nextInt(30))});
            vals.add(new BigInteger[]{p.multiply(BigInteger.TEN.pow(300 + rnd.nextInt(30))), BigInteger.ONE.add(BigInteger.valueOf(rnd.nextInt(9)))});
        }
        for (long n = (1L << 52) - 5; n < (1L << 52) + 5; n++) vals.add(new BigInteger[]{BigInteger.valueOf(n), BigInteger.ONE});
        for (long n = (1L << 53) - 5; n < (1L << 53) + 5; n++) vals.add(new BigInteger[]{BigInteger.valueOf(n), BigInteger.ONE});
        List<Double> ds = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            ds.add(Double.parseDouble(BigDecimal.valueOf(rnd.nextInt(2000000) - 1000000, rnd.nextInt(10)).toString()));
            ds.add(Double.longBitsToDouble(rnd.nextLong()));
            ds.add(rnd.nextDouble() * 100);
        }
        ds.add(0.0); ds.add(-0.0); ds.add(1.0); ds.add(0.1); ds.add(1e-300); ds.add(Double.MIN_VALUE); ds.add(Double.MAX_VALUE);
        ds.removeIf(d -> Double.isNaN(d) || Double.isInfinite(d));
        for (int k = 1; k < a.length; k++) {
            Path dir = Path.of(a[k]);
            String det = Files.readString(dir.resolve("details.txt"));
            R m;
            try { m = load(Files.readAllBytes(dir.resolve("org.fclcert.eval.Rational.class"))); }
            catch (Throwable t) { System.out.println(dir.getFileName() + " LOADFAIL " + t); continue; }
            long maxU = 0, diffs = 0; String worst = "";
            for (BigInteger[] v : vals) {
                double x = td(orig, v[0], v[1]);
                if (System.getenv("NORMAL") != null && (Math.abs(x) < 1e-290 || Math.abs(x) > 1e290)) continue;
                double y;
                try { y = td(m, v[0], v[1]); } catch (Throwable t) { y = Double.NaN; }
                long u = ulps(x, y);
                if (u != 0) { diffs++; if (u > maxU) { maxU = u; worst = v[0] + "/" + v[1] + " -> " + x + " vs " + y; } }
            }
            long sdDiff = 0; String sdW = "";
            for (double d : ds) {
                try {
                    BigDecimal x = (BigDecimal) orig.sd.invoke(null, d), y = (BigDecimal) m.sd.invoke(null, d);
                    if (x.compareTo(y) != 0) { sdDiff++; if (sdW.isEmpty() || rnd.nextInt(50)==0) sdW = d + ": " + x + " vs " + y; }
                } catch (Exception e) { sdDiff++; sdW = d + " " + e.getCause(); }
            }
            String line = det.replaceAll(".*method=(\\w+),.*indexes=\\[(\\d+)\\], mutator=[\\w.]*\\.(\\w+)\\].*lineNumber=(\\d+), description=([^,]*),.*", "$4 $1 $2 $3 $5").trim();
            System.out.println(dir.getFileName() + " | " + line + " | toDouble diffs " + diffs + "/" + vals.size() + " max ulps " + maxU + (maxU > 0 ? " e.g. " + (worst.length() > 200 ? worst.substring(0, 200) : worst) : "") + " | shortestDecimal diffs " + sdDiff + "/" + ds.size() + " " + sdW);
        }
    }
}
